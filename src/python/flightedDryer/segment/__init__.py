"""segment: the drum segment, a dryer's own curtain scene (drumSegmentCase): the
drum's cross-section one flight stagger long, meshed from the flight dictionary,
every releasing flight's curtain at once, run with curtainFoam and measured.

  inputs  the options checked, and the inputs' signature (resume)
  run     the steps: mesh, picture, curtains, solve, results; the swap into DIR
  main    drumSegmentCase's main
"""
