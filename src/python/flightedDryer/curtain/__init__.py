"""curtain: one falling-curtain case with curtainFoam, as curtainCase runs it.

  settings     the constants of a run: file names, tolerances, allowed ranges
  dictionaries the template's and the case's dictionaries, errors mapped to the run's
  inputs       the options checked against the template, before anything runs
  setUp        the case made from the template at the operating point
  results      the steady window's means, the result and landing CSVs
  folders      the inputs' signature and the case folder's files (kept, swapped, pruned)
  run          the solve with its gentler second stage, and the resume
  segment      -scene drumSegment: curtainCase's options passed to drumSegmentCase
  main         curtainCase's main
"""
