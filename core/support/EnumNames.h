#pragma once
// Stable names of enum values for files and the command line: each enum keeps one table of
// {value, "name"} pairs, and these two functions read it both ways.

#include <cstddef>
#include <optional>
#include <string_view>
#include <utility>

namespace facet {

template <typename Enum, std::size_t N>
std::optional<Enum> enumFromName(const std::pair<Enum, const char*> (&table)[N], std::string_view name)
{
    for (const auto& [value, text] : table)
        if (name == text)
            return value;
    return std::nullopt;
}

template <typename Enum, std::size_t N>
const char* enumName(const std::pair<Enum, const char*> (&table)[N], Enum value)
{
    for (const auto& [v, text] : table)
        if (v == value)
            return text;
    return "";
}

} // namespace facet
