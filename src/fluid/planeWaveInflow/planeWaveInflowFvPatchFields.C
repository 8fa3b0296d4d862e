#include "planeWaveInflowFvPatchFields.H"
#include "addToRunTimeSelectionTable.H"
#include "volFields.H"
#include "keywordCheck.H"

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * //

namespace
{

//- The entries a T or U entry of the type may have: p's parameters are a
//  message of their own; any other unknown or duplicated keyword is the
//  project's keyword check's error (closest valid keyword suggested;
//  issue 19, adv28 p62: an unknown entry was ignored)
void checkNoParameters
(
    const Foam::dictionary& dict,
    const Foam::word& field,
    const Foam::word& patch
)
{
    using namespace Foam;
    for (const char* k : {"columnHeight", "pulse", "file",
                          "ambientPressure", "ambientTemperature"})
    {
        if (dict.found(k, keyType::LITERAL))
        {
            FatalIOErrorInFunction(dict)
                << "Entry " << k << " in the planeWaveInflow condition of "
                << field << " on patch " << patch << ": only p's entry "
                << "has parameters (columnHeight, pulse, file); "
                << field << " takes type and value" << exit(FatalIOError);
        }
    }
    foamTools::checkKeywords(dict, {"type", "patchType", "value"});
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * Scalar: p and T  * * * * * * * * * * * * //

Foam::planeWaveInflowFvPatchScalarField::planeWaveInflowFvPatchScalarField
(
    const fvPatch& p,
    const DimensionedField<scalar, volMesh>& iF
)
:
    fixedValueFvPatchScalarField(p, iF)
{}


Foam::planeWaveInflowFvPatchScalarField::planeWaveInflowFvPatchScalarField
(
    const fvPatch& p,
    const DimensionedField<scalar, volMesh>& iF,
    const dictionary& dict
)
:
    fixedValueFvPatchScalarField(p, iF, dict)
{
    const word& name = iF.name();
    if (name == "p")
    {
        // With the initial p next to the patch (read before the boundary):
        // the ambient pressure of a new start, not the cells after the
        // first stage, which a 'value' entry other than the water's has
        // already changed
        wave_.reset
        (
            new planeWaveInflowWave(dict, p, p.patchInternalField(iF))
        );
    }
    else if (name == "T")
    {
        checkNoParameters(dict, name, p.name());
    }
    else
    {
        FatalIOErrorInFunction(dict)
            << "planeWaveInflow on patch " << p.name() << " of field "
            << name << ": the type sets p, T and U only"
            << exit(FatalIOError);
    }
}


Foam::planeWaveInflowFvPatchScalarField::planeWaveInflowFvPatchScalarField
(
    const planeWaveInflowFvPatchScalarField& ptf,
    const fvPatch& p,
    const DimensionedField<scalar, volMesh>& iF,
    const fvPatchFieldMapper& mapper
)
:
    fixedValueFvPatchScalarField(ptf, p, iF, mapper),
    wave_
    (
        ptf.wave_.valid() ? new planeWaveInflowWave(ptf.wave_()) : nullptr
    )
{}


Foam::planeWaveInflowFvPatchScalarField::planeWaveInflowFvPatchScalarField
(
    const planeWaveInflowFvPatchScalarField& ptf
)
:
    fixedValueFvPatchScalarField(ptf),
    wave_
    (
        ptf.wave_.valid() ? new planeWaveInflowWave(ptf.wave_()) : nullptr
    )
{}


Foam::planeWaveInflowFvPatchScalarField::planeWaveInflowFvPatchScalarField
(
    const planeWaveInflowFvPatchScalarField& ptf,
    const DimensionedField<scalar, volMesh>& iF
)
:
    fixedValueFvPatchScalarField(ptf, iF),
    wave_
    (
        ptf.wave_.valid() ? new planeWaveInflowWave(ptf.wave_()) : nullptr
    )
{}


const Foam::planeWaveInflowWave&
Foam::planeWaveInflowFvPatchScalarField::wave(const fvPatch& patch)
{
    const volScalarField& p =
        patch.boundaryMesh().mesh().lookupObject<volScalarField>("p");
    const fvPatchScalarField& pp = p.boundaryField()[patch.index()];
    if
    (
        !isA<planeWaveInflowFvPatchScalarField>(pp)
     || !refCast<const planeWaveInflowFvPatchScalarField>(pp).wave_.valid()
    )
    {
        FatalErrorInFunction
            << "Patch " << patch.name() << ": planeWaveInflow on T or U "
            << "needs p of the same type there (its entry has the wave); "
            << "p is " << pp.type() << exit(FatalError);
    }
    return refCast<const planeWaveInflowFvPatchScalarField>(pp).wave_();
}


void Foam::planeWaveInflowFvPatchScalarField::updateCoeffs()
{
    if (updated())
    {
        return;
    }
    scalarField pb, Tb;
    vectorField Ub;
    wave(patch()).state(patch(), pb, Ub, Tb);
    operator==(wave_.valid() ? pb : Tb);
    fixedValueFvPatchScalarField::updateCoeffs();
}


void Foam::planeWaveInflowFvPatchScalarField::write(Ostream& os) const
{
    fvPatchScalarField::write(os);
    if (wave_.valid())
    {
        wave_->write(os);
    }
    writeEntry("value", os);
}


// * * * * * * * * * * * * * * * * Vector: U  * * * * * * * * * * * * * * //

Foam::planeWaveInflowFvPatchVectorField::planeWaveInflowFvPatchVectorField
(
    const fvPatch& p,
    const DimensionedField<vector, volMesh>& iF
)
:
    fixedValueFvPatchVectorField(p, iF)
{}


Foam::planeWaveInflowFvPatchVectorField::planeWaveInflowFvPatchVectorField
(
    const fvPatch& p,
    const DimensionedField<vector, volMesh>& iF,
    const dictionary& dict
)
:
    fixedValueFvPatchVectorField(p, iF, dict)
{
    checkNoParameters(dict, iF.name(), p.name());
}


Foam::planeWaveInflowFvPatchVectorField::planeWaveInflowFvPatchVectorField
(
    const planeWaveInflowFvPatchVectorField& ptf,
    const fvPatch& p,
    const DimensionedField<vector, volMesh>& iF,
    const fvPatchFieldMapper& mapper
)
:
    fixedValueFvPatchVectorField(ptf, p, iF, mapper)
{}


Foam::planeWaveInflowFvPatchVectorField::planeWaveInflowFvPatchVectorField
(
    const planeWaveInflowFvPatchVectorField& ptf
)
:
    fixedValueFvPatchVectorField(ptf)
{}


Foam::planeWaveInflowFvPatchVectorField::planeWaveInflowFvPatchVectorField
(
    const planeWaveInflowFvPatchVectorField& ptf,
    const DimensionedField<vector, volMesh>& iF
)
:
    fixedValueFvPatchVectorField(ptf, iF)
{}


void Foam::planeWaveInflowFvPatchVectorField::updateCoeffs()
{
    if (updated())
    {
        return;
    }
    scalarField pb, Tb;
    vectorField Ub;
    planeWaveInflowFvPatchScalarField::wave(patch())
        .state(patch(), pb, Ub, Tb);
    operator==(Ub);
    fixedValueFvPatchVectorField::updateCoeffs();
}


// * * * * * * * * * * * * * * * * Registration  * * * * * * * * * * * * * //

namespace Foam
{
    makePatchTypeField(fvPatchScalarField, planeWaveInflowFvPatchScalarField);
    makePatchTypeField(fvPatchVectorField, planeWaveInflowFvPatchVectorField);
}

// ************************************************************************* //
