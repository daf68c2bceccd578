#pragma once
// ASCII case folding for names Facet compares without regard to case: file extensions, colour
// space names, GL renderer strings. Unlike std::tolower it ignores the process's locale (a
// QCoreApplication sets it from the environment), so the same bytes always compare the same.

#include <string>

namespace facet {

inline std::string asciiLowercase(std::string text)
{
    for (char& c : text)
        if (c >= 'A' && c <= 'Z')
            c = char(c - 'A' + 'a');
    return text;
}

} // namespace facet
