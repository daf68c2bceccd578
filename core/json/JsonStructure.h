#pragma once
// A check of a JSON text's shape made before any parser sees it (issue 29): how deep its arrays
// and objects nest, and, where asked, whether an object holds a key twice.
//
// Why before parsing: the parsers Facet uses recurse. tinygltf turns nlohmann-json's tree into
// its own values with one call per level, and a 40 KB glTF whose "extras" nest 20 000 arrays deep
// overflowed the stack (a crash of `facet render`, and of a window with unsaved edits on File >
// Open or Import Asset). The scan is one loop with a stack of its own in the heap, so no text can
// exhaust the thread's stack here. Qt's QJsonDocument stops at 1024 levels by itself; Facet's own
// files are held to the same bound as glTF.
//
// Duplicate keys: QJsonDocument keeps the last of two values under one key and nlohmann-json
// keeps the first, so a project saying "roughness" twice meant one thing to one reader and
// another to the next, silently. Facet's own files (projects, presets, export templates) are
// refused naming the key's JSON path; glTF is not held to it (the glTF specification leaves
// duplicate keys to JSON's "SHOULD be unique", and other renderers load such assets).
//
// The scan is lenient about everything else: it stops quietly on text that is not JSON and leaves
// the syntax error to the parser that follows, which reports it with its own position.

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

namespace facet {

// Far deeper than any file Facet reads needs (Facet's projects nest 6 levels; the Khronos sample
// assets at most 9, their extras included) and far shallower than the 10 000 levels at which
// tinygltf starts to use megabytes of stack (a worker thread's stack is 8 MiB here, and a
// sanitizer build's frames are several times larger).
inline constexpr int kMaxJsonDepth = 256;

struct JsonStructureRules {
    int maxDepth = kMaxJsonDepth;
    bool refuseDuplicateKeys = true;
};

// "line L, column C" of byte `offset` in `text`: 1-based, columns in characters (UTF-8
// continuation bytes start none), as every JSON message of Facet's gives a position.
std::string jsonPosition(std::string_view text, std::size_t offset);

// Nothing when `text` is within the rules (or is not JSON at all: the parser says so); else one
// line saying where and what, e.g. "line 3, column 18: arrays and objects nest deeper than 256
// levels" or "line 7, column 9: materials[0]: the key \"roughness\" appears twice in one object".
std::optional<std::string> jsonStructureProblem(std::string_view text, const JsonStructureRules& rules = {});

} // namespace facet
