/*---------------------------------------------------------------------------*\
  flightedDryer: curtainFoam
-------------------------------------------------------------------------------
Application
    curtainFoam

Group
    grpMultiphaseSolvers

Description
    Falling curtains of solids in a gas: incompressible, isothermal gas with
    RANS turbulence (any PhaseIncompressible model: kEpsilon, realizableKE,
    kOmegaSST, laminar) and one or more dispersed particle size classes,
    each with its own continuity and momentum, coupled by interphase drag
    from the particleDragModel family (libcurtainModels), and optionally
    with each other by collisions (particleParticleDragModel family). Gravity acts on
    the solids; the gas pressure is p_rgh = p - rho_g g.h.

    Physics for dilute curtains (solids fraction mostly below 1e-2; Lee
    2008 section 6.4: no kinetic theory, no particle pressure): the
    particle phases are pressureless; their momentum is written per unit
    particle volume so it stays well posed where alpha -> 0; drag is
    implicit in both phases through a partial elimination; the slot region
    (alpha ~ 0.1-0.2) is guarded by alphaMax. Solids transport: implicit
    upwind, or (in the alpha.* solver dictionary) upwind plus a higher-order
    correction: deferredCorr (the previous iteration's difference to the
    div(phi,alpha) flux; its steady answer does not depend on the local
    step) or MULESCorr (MULES-limited; bounded at every step).

    Gas sources from constant/fvOptions (OpenFOAM's fvOptions on U.<gas>,
    e.g. meanVelocityForce driving a periodic segment at its mean axial
    gas velocity; on k and epsilon the particleTurbulenceInteraction
    models of libcurtainModels).

    Time stepping: transient (Euler ddt, maxCo adjustable step) or, with
    ddtSchemes { default localEuler; }, a pseudo-transient march to the
    steady state with local time steps (PIMPLE maxCo, maxCoParticles).

    Stops with the cause and the last good time when a solids fraction
    leaves [0, 1] or a field turns NaN.

\*---------------------------------------------------------------------------*/

#include "fvCFD.H"
#include "profiling.H"
#include "sigFpe.H"
#include "singlePhaseTransportModel.H"
#include "PhaseIncompressibleTurbulenceModel.H"
#include "pimpleControl.H"
#include "fvOptions.H"
#include "localEulerDdtScheme.H"
#include "fvcSmooth.H"
#include "constrainPressure.H"
#include "constrainHbyA.H"
#include "CMULES.H"
#include "EulerDdtScheme.H"
#include "gaussConvectionScheme.H"
#include "upwind.H"
#include "hexMatcher.H"
#include "particleClass.H"
#include "turbulentDispersionModel.H"
#include "particleParticleDragModel.H"

#include <cmath>

#include "readStartField.H"
#include "faceReconstruction.H"
#include "startUp.H"

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

int main(int argc, char *argv[])
{
    argList::addNote
    (
        "Falling curtains: incompressible gas (RANS) and one or more"
        " pressureless particle size classes with implicit drag;"
        " transient or local-time-stepping to the steady state."
    );

    #include "addCheckCaseOptions.H"
    #include "setRootCaseLists.H"

    // A diverging iteration shows as NaN and is stopped by checkFields.H
    // with its cause and the last good time on disk, rather than by a
    // floating-point trap inside a linear solver (which names neither).
    // An explicit FOAM_SIGFPE in the environment still decides.
    if (Foam::getEnv("FOAM_SIGFPE").empty())
    {
        sigFpe::unset(false);
    }
    #include "createTime.H"
    #include "createMesh.H"
    #include "createControl.H"
    #include "createTimeControls.H"
    #include "createRDeltaT.H"
    #include "createFields.H"
    #include "startFields.H"
    #include "createFvOptions.H"

    turbulence->validate();

    if (!LTS)
    {
        #include "CourantNo.H"
        #include "setInitialDeltaT.H"
    }

    Info<< "\nStarting time loop\n" << endl;

    while (runTime.run())
    {
        #include "readTimeControls.H"
        #include "checkCourantLimits.H"

        // this iteration's start-up phase (startUp.H): its Courant number and
        // smoothing (setRDeltaT.H) and its pressure corrections (below)
        const startUpPhase startUp
        (
            LTS ? readStartUp(pimple.dict(), runTime.timeIndex()) : startUpPhase()
        );

        if (LTS)
        {
            addProfiling(rDeltaT, "curtainFoam::localTimeStep");
            #include "setRDeltaT.H"
        }
        else
        {
            #include "CourantNo.H"
            #include "setDeltaT.H"
        }

        ++runTime;

        Info<< "Time = " << runTime.timeName() << nl << endl;

        // (sections timed when the case's controlDict has profiling { active
        // yes; }: <time>/uniform/profiling, tests/benchmarks/curtainPeer PROFILE=1;
        // triggers stopped by hand where the included code's variables live on)
        while (pimple.loop())
        {
            profilingTrigger alphaProf("curtainFoam::solidsFractions");
            #include "alphaEqns.H"
            alphaProf.stop();
            profilingTrigger UEqnsProf("curtainFoam::momentumPredictor");
            #include "UEqns.H"
            UEqnsProf.stop();

            // the start-up phase's extra pressure corrections
            const label extraCorrections
            (
                startUp.active
              ? max(startUp.nCorrectors - pimple.dict().getOrDefault<label>("nCorrectors", 1), label(0))
              : label(0)
            );
            while (pimple.correct())
            {
                addProfiling(pEqn, "curtainFoam::pressure");
                for (label extra = 0; extra <= extraCorrections; ++extra)
                {
                    #include "pEqn.H"
                }
            }

            profilingTrigger UpProf("curtainFoam::solidsMomentum");
            #include "UpEqns.H"
            UpProf.stop();

            if (pimple.turbCorr())
            {
                addProfiling(turb, "curtainFoam::turbulence");
                turbulence->correct();
            }
        }

        profilingTrigger checkProf("curtainFoam::checkFields");
        #include "checkFields.H"
        checkProf.stop();

        runTime.write();
        if (runTime.writeTime())
        {
            lastGoodTime = runTime.timeName();
            // Every field of this time is written and closed: mark the time
            // folder a whole restart point (curtainCase resumes only from a
            // marked time; a kill inside the write leaves it unmarked)
            mkDir(runTime.timePath()/"uniform");
            OFstream(runTime.timePath()/"uniform"/"curtainFoam.written")()
                << runTime.timeName() << nl;
        }

        runTime.printExecutionTime(Info);
    }

    Info<< "End\n" << endl;

    return 0;
}


// ************************************************************************* //
