// JSON text -> nlohmann::json for the samples' files, with the JSON Pointer (RFC 6901) of the
// offending value in every error. nlohmann's own parse() reports syntax errors with a line and
// column only, and reports a number beyond double range (1e400) as an out_of_range exception
// that carries neither; both come through here with the path of the value being read.
// Nesting is capped: no file of ours needs more than a few levels, and a bounded depth keeps
// every later operation on the value (printing, comparing, copying) far from the stack limit.
#pragma once

#include <nlohmann/json.hpp>

#include <cstddef>
#include <string>

namespace pfs {

/// Parses `text` (comments allowed). Throws pfs::Error("<file>: <pointer>: <reason>"), the
/// pointer being that of the value where reading stopped ("(top level)" for the root).
nlohmann::json read_json(const std::string& text, const std::string& file, size_t max_depth = 32);

/// The JSON Pointer of member `key` (or array index, written as decimal) of the value at
/// `parent`: "/fill" + "0" -> "/fill/0"; '~' and '/' in keys are escaped as ~0 and ~1.
std::string pointer_join(const std::string& parent, const std::string& key);

/// `pointer`, or "(top level)" for the root's empty pointer: how messages name a location.
std::string pointer_text(const std::string& pointer);

} // namespace pfs
