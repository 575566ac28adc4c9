/// \file
/// The scene reader's JSON document: nlohmann's ordered DOM (keys in file order), read by a
/// SAX handler that refuses duplicate keys, nesting beyond 128 levels and NUL bytes, and places
/// a syntax error at its line and column. Also the quoting every scene message uses.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

namespace tamias2d::io::scene_detail {

using ojson = nlohmann::ordered_json;

/// What a message quotes of a user's text: control characters escaped as JSON writes them (a
/// key or name with a newline stays on one line, and a terminal sees no escape sequence), and
/// at most `max` bytes of it, cut at a character boundary, the rest counted.
std::string printable(std::string_view s, std::size_t max);

/// A JSON pointer as messages show it: each token printable and short, and a deep pointer
/// (nesting up to the parser's limit) shortened to its first and last levels.
std::string shown_pointer(std::string_view pointer);

/// A user's string (key, name, kind) in a message: 'text', escaped and shortened.
std::string quote(std::string_view s);

/// RFC 6901 escaping of one reference token.
std::string escape_token(std::string_view key);

/// Appends the member `key` to `object` (an object that has no such key: the caller knows it),
/// in constant amortised time, and returns its value.
ojson& append_member(ojson& object, std::string key, ojson value);

/// The document of `text`; a SceneError (at a line and column, or at the pointer of a
/// duplicate key or of too deep a nesting) if it is no JSON text the scene format takes.
ojson parse_json(std::string_view text, const std::string& origin);

} // namespace tamias2d::io::scene_detail
