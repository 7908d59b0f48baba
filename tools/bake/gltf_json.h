// SPDX-License-Identifier: MIT
// A glTF file's JSON, parsed only once it is known to be bounded (size, nesting,
// value count: GltfLimits): nlohmann's SAX parser keeps its stack on the heap and
// stops at the first excess, so hostile nesting never reaches a recursive parser.
#pragma once

#include <cstddef>
#include <string>

#include <nlohmann/json.hpp>

namespace frusta {

using Json = nlohmann::json;

// The JSON in text[0, size) as a tree; false with the reason in *why when it breaks a
// limit or is not JSON.
bool parse_bounded_json(const char* text, size_t size, Json* out, std::string* why);

}  // namespace frusta
