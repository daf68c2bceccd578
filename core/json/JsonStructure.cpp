// The shape check of JSON texts made before parsing (core/json/JsonStructure.h).

#include "core/json/JsonStructure.h"

#include <cstdint>
#include <unordered_set>
#include <vector>

namespace facet {

namespace {

struct Frame {
    bool object = false;
    bool expectKey = false; // an object after '{' or ',': the next string is a key
    std::size_t index = 0; // an array's element index
    std::string key; // an object's current key
    std::unordered_set<std::string> keys; // an object's keys so far (when duplicates are refused)
};

// The JSON path of the value frame `count - 1` holds, as core's readers write paths
// ("materials[0].maps").
std::string pathOf(const std::vector<Frame>& frames, std::size_t count)
{
    std::string path;
    for (std::size_t i = 0; i + 1 < count; ++i) {
        if (frames[i].object) {
            if (!path.empty())
                path += '.';
            path += frames[i].key;
        } else {
            path += '[';
            path += std::to_string(frames[i].index);
            path += ']';
        }
    }
    return path;
}

void appendUtf8(std::string& out, std::uint32_t code)
{
    if (code < 0x80) {
        out += char(code);
    } else if (code < 0x800) {
        out += char(0xC0 | (code >> 6));
        out += char(0x80 | (code & 0x3F));
    } else if (code < 0x10000) {
        out += char(0xE0 | (code >> 12));
        out += char(0x80 | ((code >> 6) & 0x3F));
        out += char(0x80 | (code & 0x3F));
    } else {
        out += char(0xF0 | (code >> 18));
        out += char(0x80 | ((code >> 12) & 0x3F));
        out += char(0x80 | ((code >> 6) & 0x3F));
        out += char(0x80 | (code & 0x3F));
    }
}

std::optional<std::uint32_t> hex4(std::string_view text, std::size_t at)
{
    if (at + 4 > text.size())
        return std::nullopt;
    std::uint32_t value = 0;
    for (std::size_t i = at; i < at + 4; ++i) {
        const char c = text[i];
        value <<= 4;
        if (c >= '0' && c <= '9')
            value |= std::uint32_t(c - '0');
        else if (c >= 'a' && c <= 'f')
            value |= std::uint32_t(c - 'a' + 10);
        else if (c >= 'A' && c <= 'F')
            value |= std::uint32_t(c - 'A' + 10);
        else
            return std::nullopt;
    }
    return value;
}

// Reads the string whose opening quote is at `at`; `end` receives the offset after its closing
// quote. The decoded text goes to `decoded` when asked (keys are compared decoded: "a" and
// "\u0061" are one key). False on a string that is not JSON (the parser reports it).
bool readString(std::string_view text, std::size_t at, std::size_t* end, std::string* decoded)
{
    std::size_t i = at + 1;
    while (i < text.size()) {
        const char c = text[i];
        if (c == '"') {
            *end = i + 1;
            return true;
        }
        if (c != '\\') {
            if (decoded)
                *decoded += c;
            ++i;
            continue;
        }
        if (i + 1 >= text.size())
            return false;
        const char escaped = text[i + 1];
        i += 2;
        if (escaped == 'u') {
            std::optional<std::uint32_t> code = hex4(text, i);
            if (!code)
                return false;
            i += 4;
            // A high surrogate followed by a low one is one code point.
            if (*code >= 0xD800 && *code < 0xDC00 && i + 1 < text.size() && text[i] == '\\'
                && text[i + 1] == 'u')
                if (const std::optional<std::uint32_t> low = hex4(text, i + 2);
                    low && *low >= 0xDC00 && *low < 0xE000) {
                    *code = 0x10000 + ((*code - 0xD800) << 10) + (*low - 0xDC00);
                    i += 6;
                }
            if (decoded)
                appendUtf8(*decoded, *code);
            continue;
        }
        if (!decoded)
            continue;
        switch (escaped) {
        case 'b':
            *decoded += '\b';
            break;
        case 'f':
            *decoded += '\f';
            break;
        case 'n':
            *decoded += '\n';
            break;
        case 'r':
            *decoded += '\r';
            break;
        case 't':
            *decoded += '\t';
            break;
        default:
            *decoded += escaped; // '"', '\\', '/' (and what the parser will refuse)
        }
    }
    return false;
}

} // namespace

std::string jsonPosition(std::string_view text, std::size_t offset)
{
    int line = 1;
    int column = 1;
    for (std::size_t i = 0; i < offset && i < text.size(); ++i) {
        const auto byte = static_cast<unsigned char>(text[i]);
        if (byte == '\n') {
            ++line;
            column = 1;
        } else if ((byte & 0xC0) != 0x80) {
            ++column;
        }
    }
    return "line " + std::to_string(line) + ", column " + std::to_string(column);
}

std::optional<std::string> jsonStructureProblem(std::string_view text, const JsonStructureRules& rules)
{
    std::vector<Frame> frames;
    std::size_t i = 0;
    while (i < text.size()) {
        const char c = text[i];
        switch (c) {
        case '{':
        case '[':
            if (int(frames.size()) >= rules.maxDepth)
                return jsonPosition(text, i) + ": arrays and objects nest deeper than "
                    + std::to_string(rules.maxDepth) + " levels";
            frames.push_back(Frame {});
            frames.back().object = c == '{';
            frames.back().expectKey = c == '{';
            ++i;
            break;
        case '}':
        case ']':
            if (frames.empty())
                return std::nullopt; // not JSON: the parser says where
            frames.pop_back();
            ++i;
            break;
        case ',':
            if (!frames.empty()) {
                if (frames.back().object)
                    frames.back().expectKey = true;
                else
                    ++frames.back().index;
            }
            ++i;
            break;
        case '"': {
            std::size_t end = 0;
            const bool isKey = !frames.empty() && frames.back().object && frames.back().expectKey;
            std::string key;
            if (!readString(text, i, &end, isKey ? &key : nullptr))
                return std::nullopt;
            if (isKey) {
                Frame& frame = frames.back();
                frame.expectKey = false;
                if (rules.refuseDuplicateKeys && !frame.keys.insert(key).second) {
                    const std::string path = pathOf(frames, frames.size());
                    return jsonPosition(text, i) + ": " + (path.empty() ? std::string() : path + ": ")
                        + "the key \"" + key + "\" appears twice in one object";
                }
                frame.key = std::move(key);
            }
            i = end;
            break;
        }
        default:
            ++i; // whitespace, ':', numbers and literals
        }
    }
    return std::nullopt;
}

} // namespace facet
