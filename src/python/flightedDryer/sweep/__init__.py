"""sweep: a drift-table sweep, as buildDriftTable runs it.

  settings    the dictionary's entries, the table's axes (from the C++ side), file names
  dictionary  the sweep dictionary read and checked (box and drumSegment scenes)
  plan        the curtainCase runs of the grid, their folders and arguments, resume
  localPool   the runs on this machine, -jobs at a time, with a retry
  slurm       the runs as one Slurm job array with a collect step
  table       the table written from the finished runs (through writeDriftTable)
  main        buildDriftTable's main
"""
