"""plots: the pictures of the plot tools (plotCurtain, plotDriftTable).

  curtainPlot     a curtainFoam solution on two planes, and its VTK
  driftTablePlot  V_c/V_g and drift across a drift table's grid
"""
