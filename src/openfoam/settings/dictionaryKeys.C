/*---------------------------------------------------------------------------*\
  dropletFiber: stochastic droplet-fiber coupling for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "dictionaryKeys.H"
#include "error.H"

#include <algorithm>
#include <cctype>
#include <string>
#include <vector>

// * * * * * * * * * * * * * * * Local Functions  * * * * * * * * * * * * * //

namespace
{

std::string lowerCase(const std::string& s)
{
    std::string lower(s);
    for (char& c : lower)
    {
        c = char(std::tolower(static_cast<unsigned char>(c)));
    }
    return lower;
}


//- One starts the other (e.g. youngs, youngsModulus), both of 4 or more letters
bool isBeginningOf(const std::string& a, const std::string& b)
{
    const std::string& shorter = a.size() < b.size() ? a : b;
    const std::string& longer = a.size() < b.size() ? b : a;
    return shorter.size() >= 4 && longer.compare(0, shorter.size(), shorter) == 0;
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * Global Functions  * * * * * * * * * * * * //

Foam::label Foam::dropletFiber::keyDistance(const word& a, const word& b)
{
    // Optimal string alignment distance (Damerau-Levenshtein without
    // repeated edits of one substring): a swap of two letters counts one
    const std::string s = lowerCase(a);
    const std::string t = lowerCase(b);
    const std::size_t n = s.size();
    const std::size_t m = t.size();
    std::vector<std::vector<label>> d(n + 1, std::vector<label>(m + 1, 0));
    for (std::size_t i = 0; i <= n; ++i)
    {
        d[i][0] = label(i);
    }
    for (std::size_t j = 0; j <= m; ++j)
    {
        d[0][j] = label(j);
    }
    for (std::size_t i = 1; i <= n; ++i)
    {
        for (std::size_t j = 1; j <= m; ++j)
        {
            const label cost = s[i - 1] == t[j - 1] ? 0 : 1;
            d[i][j] =
                std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + cost});
            if (i > 1 && j > 1 && s[i - 1] == t[j - 2] && s[i - 2] == t[j - 1])
            {
                d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
            }
        }
    }
    return d[n][m];
}


Foam::word Foam::dropletFiber::closestKey
(
    const word& key,
    const wordList& allowed
)
{
    word best;
    label bestDistance = labelMax;
    for (const word& candidate : allowed)
    {
        const label distance = keyDistance(key, candidate);
        // Close: about one edit in three letters (at least one edit), or
        // the beginning of the other
        const label longer = label(std::max(key.size(), candidate.size()));
        const bool close =
            distance <= std::max(label(1), longer/3)
         || isBeginningOf(lowerCase(key), lowerCase(candidate));
        if (close && distance < bestDistance)
        {
            best = candidate;
            bestDistance = distance;
        }
    }
    return best;
}


void Foam::dropletFiber::checkKeys
(
    const dictionary& dict,
    const wordList& allowed
)
{
    for (const entry& e : dict)
    {
        const word& key = e.keyword();
        if (allowed.found(key))
        {
            continue;
        }
        const word suggestion = closestKey(key, allowed);
        std::string hint;
        if (suggestion.empty())
        {
            hint = "allowed are";
            for (const word& k : allowed)
            {
                hint += (k == allowed.first() ? " " : ", ") + k;
            }
            hint += ".";
        }
        else
        {
            hint = "did you mean '" + suggestion + "'?";
        }
        FatalIOErrorInFunction(dict)
            << "Entry '" << key << "' in dictionary '"
            << dict.name().name().c_str() << "' is not known: "
            << hint.c_str() << exit(FatalIOError);
    }
}


Foam::wordList Foam::dropletFiber::joinedKeys
(
    const wordList& a,
    const wordList& b
)
{
    wordList keys(a);
    keys.append(b);
    return keys;
}


Foam::wordList Foam::dropletFiber::joinedKeys
(
    std::initializer_list<wordList> lists
)
{
    wordList keys;
    for (const wordList& list : lists)
    {
        keys.append(list);
    }
    return keys;
}

// ************************************************************************* //
