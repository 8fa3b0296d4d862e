/*---------------------------------------------------------------------------*\
Application
    foamUnitTests

Description
    GoogleTest runner of the unit tests of the OpenFOAM-side libraries
    (src/fsi, src/thermophysicalModels/rhoEThermo, src/riemannFluxes,
    src/foamTools), which build their small cases in code
    (foamTestCase.H) and run without a solver.

    FatalError and FatalIOError throw (Foam::error, Foam::IOerror) instead
    of ending the process, so that a test can check an input error's
    message. OpenFOAM's Info output is off unless FOAM_UNIT_VERBOSE is set.

Usage
    \verbatim
        . etc/bashrc
        foamUnitTests                               # every suite
        foamUnitTests --gtest_filter='couplingScheme.*'
        foamUnitTests --gtest_list_tests
    \endverbatim

\*---------------------------------------------------------------------------*/

#include "error.H"
#include "messageStream.H"
#include "OSspecific.H"

#include <gtest/gtest.h>

int main(int argc, char** argv)
{
    ::testing::InitGoogleTest(&argc, argv);
    Foam::FatalError.throwExceptions();
    Foam::FatalIOError.throwExceptions();
    if (Foam::getEnv("FOAM_UNIT_VERBOSE").empty())
    {
        Foam::messageStream::level = 0;
    }
    return RUN_ALL_TESTS();
}
