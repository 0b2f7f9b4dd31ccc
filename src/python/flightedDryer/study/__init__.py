"""study: a dryer study in one command (dryerStudy): from a dryer's description
to its residence time, holdup and a report.

  description  the description (YAML: the drum model's sections and `study:`) read strictly
  plan         the drift table the dryer needs: its grid from the drum model's own
               queries, its runs and their CPU estimate
  routes       the drum model run with the CFD table, Eq 142, lone particles and the
               table's error band
  report       the HTML report with its pictures
  main         dryerStudy's main
"""
