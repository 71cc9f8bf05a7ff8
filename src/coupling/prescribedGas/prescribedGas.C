/*---------------------------------------------------------------------------*\
  rarefiedMultiphaseFoam
\*---------------------------------------------------------------------------*/

#include "prescribedGas.H"
#include "inputChecks.H"
#include "IFstream.H"
#include "Tuple2.H"

#include <cmath>

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace Foam
{

//- Stop: a table entry is bad (value and valid range as text)
[[noreturn]] static void badRow
(
    const dictionary& dict,
    const word& keyword,
    const string& value,
    const string& valid
)
{
    inputChecks::badValue(dict, keyword, value.c_str(), valid.c_str());
}

} // End namespace Foam


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::prescribedGas::readConstants(const dictionary& dict)
{
    state& g = uniform_;
    if (!muColumn_)
    {
        g.mu = inputChecks::getPositive(dict, "mu");
    }
    g.gamma = dict.get<scalar>("gamma");
    // 5/3 as written with 6 digits (1.66667) is accepted
    if (!(g.gamma > 1 && g.gamma <= 5.0/3.0*(1 + 1e-5)))
    {
        inputChecks::outOfRange(dict, "gamma", g.gamma, "(1, 5/3]");
    }
    g.R = inputChecks::getPositive(dict, "R");
    g.Pr = 4*g.gamma/(9*g.gamma - 5);
    if (dict.found("Pr"))
    {
        g.Pr = inputChecks::getPositive(dict, "Pr");
    }
}


void Foam::prescribedGas::readTable(const dictionary& dict)
{
    const wordList coordinates({"x", "y", "z", "r"});
    const word coord(dict.get<word>("coordinate"));
    coordinate_ = coordinates.find(coord);
    if (coordinate_ < 0)
    {
        inputChecks::notOneOf(dict, "coordinate", coord, coordinates);
    }
    origin_ = dict.getOrDefault<point>("origin", Zero);
    if (coordinate_ == 3)
    {
        const vector a(dict.get<vector>("axis"));
        if (!(mag(a) > VSMALL))
        {
            inputChecks::badValue(dict, "axis", a, "a vector of non-zero length");
        }
        axis_ = a/mag(a);
    }

    const wordList bounds({"error", "clamp"});
    const word outside(dict.getOrDefault<word>("outOfBounds", "error"));
    if (!bounds.found(outside))
    {
        inputChecks::notOneOf(dict, "outOfBounds", outside, bounds);
    }
    clamp_ = (outside == "clamp");

    // The rows, inline or from a file
    word keyword("table");
    string where("row ");
    List<scalarList> rows;
    if (dict.found("table") || !dict.found("file"))
    {
        dict.readEntry("table", rows);
    }
    else
    {
        keyword = "file";
        fileName name(dict.get<fileName>("file"));
        name.expand();
        IFstream is(name);
        if (!is.good())
        {
            badRow(dict, keyword, name, "a readable file");
        }
        is >> rows;
        where = name + ", row ";
    }

    if (rows.size() < 2)
    {
        badRow
        (
            dict, keyword, Foam::name(rows.size()) + " rows",
            "at least 2 rows"
        );
    }
    const label nCol = rows[0].size();
    muColumn_ = (nCol == 7);
    const labelList positive(muColumn_ ? labelList({1, 5, 6}) : labelList({1, 5}));
    const wordList names({"", "rho", "", "", "", "T", "mu"});
    forAll(rows, i)
    {
        if (rows[i].size() != nCol || (nCol != 6 && nCol != 7))
        {
            badRow
            (
                dict, keyword,
                where + Foam::name(i) + ": " + Foam::name(rows[i].size())
              + " columns",
                "6 (s rho Ux Uy Uz T) or 7 (s rho Ux Uy Uz T mu) columns, "
                "the same in every row"
            );
        }
        for (const scalar v : rows[i])
        {
            if (!std::isfinite(v))
            {
                badRow
                (
                    dict, keyword, where + Foam::name(i) + ": not finite",
                    "finite numbers"
                );
            }
        }
        if (i && !(rows[i][0] > rows[i-1][0]))
        {
            badRow
            (
                dict, keyword,
                where + Foam::name(i) + ": position "
              + Foam::name(rows[i][0]) + " after "
              + Foam::name(rows[i-1][0]),
                "positions (first column) strictly increasing"
            );
        }
        for (const label c : positive)
        {
            if (!(rows[i][c] > 0))
            {
                badRow
                (
                    dict, keyword,
                    where + Foam::name(i) + ": " + names[c] + " = "
                  + Foam::name(rows[i][c]),
                    names[c] + " in (0, inf)"
                );
            }
        }
    }

    readConstants(dict);

    List<Tuple2<scalar, scalar>> rho(rows.size()), T(rows.size()), mu(rows.size());
    List<Tuple2<scalar, vector>> U(rows.size());
    forAll(rows, i)
    {
        const scalarList& r = rows[i];
        rho[i] = Tuple2<scalar, scalar>(r[0], r[1]);
        U[i] = Tuple2<scalar, vector>(r[0], vector(r[2], r[3], r[4]));
        T[i] = Tuple2<scalar, scalar>(r[0], r[5]);
        mu[i] = Tuple2<scalar, scalar>(r[0], muColumn_ ? r[6] : uniform_.mu);
    }
    // Out-of-range points are handled in at(); the tables never see one
    const auto clamp = bounds::repeatableBounding::CLAMP;
    rho_ = interpolationTable<scalar>(rho, clamp, dictName_);
    U_ = interpolationTable<vector>(U, clamp, dictName_);
    T_ = interpolationTable<scalar>(T, clamp, dictName_);
    mu_ = interpolationTable<scalar>(mu, clamp, dictName_);
    sMin_ = rows.first()[0];
    sMax_ = rows.last()[0];

    Info<< "    prescribed gas: table of " << rows.size() << " rows in "
        << coord << " from " << sMin_ << " to " << sMax_
        << (muColumn_ ? " (mu a column)" : "")
        << ", outside: " << outside << "; gamma " << uniform_.gamma
        << " R " << uniform_.R << " Pr " << uniform_.Pr << endl;
}


Foam::scalar Foam::prescribedGas::coordinate(const point& x) const
{
    const vector d(x - origin_);
    if (coordinate_ < 3)
    {
        return d[coordinate_];
    }
    return mag(d - (d & axis_)*axis_);
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::prescribedGas::prescribedGas(const dictionary& dict)
:
    dictName_(dict.name()),
    uniform_(),
    tabulated_(dict.found("table") || dict.found("file")),
    coordinate_(0),
    origin_(Zero),
    axis_(Zero),
    clamp_(false),
    muColumn_(false),
    sMin_(0),
    sMax_(0)
{
    if (tabulated_)
    {
        readTable(dict);
        return;
    }

    state& g = uniform_;
    g.rho = inputChecks::getPositive(dict, "rho");
    g.U = dict.get<vector>("U");
    g.T = inputChecks::getPositive(dict, "T");
    readConstants(dict);
    Info<< "    prescribed gas: uniform, rho " << g.rho
        << " U " << g.U << " T " << g.T << " mu " << g.mu
        << " gamma " << g.gamma << " R " << g.R << " Pr " << g.Pr
        << endl;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::prescribedGas::state Foam::prescribedGas::at(const point& x) const
{
    if (!tabulated_)
    {
        return uniform_;
    }

    const scalar s = coordinate(x);
    if (!clamp_ && !(s >= sMin_ && s <= sMax_))
    {
        FatalErrorInFunction
            << "Point " << x << " is outside the prescribed gas table of "
            << dictName_ << nl
            << "    coordinate: " << s << nl
            << "    table range: [" << sMin_ << ", " << sMax_ << "]" << nl
            << "    Extend the table or set outOfBounds clamp."
            << exit(FatalError);
    }

    state g(uniform_);
    g.rho = rho_(s);
    g.U = U_(s);
    g.T = T_(s);
    g.mu = mu_(s);
    return g;
}


// ************************************************************************* //
