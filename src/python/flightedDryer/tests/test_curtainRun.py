"""curtainCase's reading of why curtainFoam stopped: a diverging iteration gets the
gentler second stage, a refused input does not."""
from flightedDryer.curtain.run import diverging


def test_nan_and_fast_gas_and_fpe_are_divergences():
    assert diverging("curtainFoam stopped at time 23: NaN or Inf in alpha.c0 or U.c0")
    assert diverging("curtainFoam stopped at time 6: speed of U.air 7.6e+07 m/s above maxVelocity "
                     "200 m/s (curtainProperties): the iteration diverges")
    assert diverging("floating-point exception: the solution diverged")
    # a solver's NaN residual, read back from the solver-performance data
    assert diverging("Wrong token type - expected scalar value, found on line 0: word 'nan' file: "
                     "/r/case.partial/system/data.solverPerformance.p_rgh at line 0.")
    assert diverging("Wrong token type - expected scalar value, found on line 0: word '-nan' file: x")


def test_refused_inputs_are_not():
    assert not diverging("curtainFoam stopped at time 1: total solids fraction 0.855 above alphaMax "
                         "0.62 (a pressureless curtain has packed: too high a spill rate or too low a "
                         "release velocity)")
    assert not diverging("Entry 'maxCo' = 20 outside the stable range (0 10] for local time stepping")
    assert not diverging("")
    assert not diverging("Wrong token type - expected scalar value, found on line 3: word 'fast' "
                         "file: /r/constant/curtainProperties at line 3.")
