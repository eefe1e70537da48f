#pragma once
// The small text values of manifests and options, read without a YAML library so
// every layer can use them: scalars as Mikan's YAML 1.1 types them (on/off,
// yes/no, integers, numbers) and the flow lists of list options (`branches:
// [L, R]`). io/ reads whole YAML files; these are the pieces below it.
#include "base/Result.h"

#include <optional>
#include <string>
#include <vector>

namespace rs {

// on/true/yes (also True, TRUE, On, Yes) and their opposites; nullopt otherwise.
std::optional<bool> parseBool(const std::string& text);
// Decimal, an optional leading '+' or '-', nothing else (no spaces, no 0x).
std::optional<long long> parseInteger(const std::string& text);
// As std::from_chars reads a double, with an optional leading '+'.
std::optional<double> parseNumber(const std::string& text);

// The byte offset of the first byte that does not begin a well-formed UTF-8
// sequence (overlong forms, UTF-16 surrogates and code points past U+10FFFF
// are ill-formed), or std::string::npos when the whole text is valid UTF-8.
// Names end up in JSON (glTF) and XML-like formats that refuse anything else.
std::size_t invalidUtf8Offset(const std::string& text);

// Items of a flow list given as text: "[L, R]", "['a', \"b\"]", "[]". A plain or
// quoted scalar is one item; empty text (or ~, null) none. A trailing comma and
// a "# comment" are allowed. Nested lists and maps, empty items, anchors,
// aliases, tags and block-style YAML are refused: a failure whose error (no
// file position; the caller knows where the text came from) says why.
Result<std::vector<std::string>> parseFlowList(const std::string& text);

} // namespace rs
