/// \file
/// The error a recording that cannot be read raises (Replayer, replay, recorded_calls).
#pragma once

#include <cstddef>
#include <stdexcept>
#include <string>

#include "tamias2d/export.hpp"

namespace tamias2d {

/// A recording refused before anything is replayed: not a recording (magic), of another format
/// version, truncated, changed (checksum), or with a record that cannot be read, named by its
/// byte offset, its field and the rule it breaks. what(): "recording refused at byte 40,
/// records[3].argument: cut short: 8 bytes needed, 2 left (truncated)".
struct TAMIAS2D_EXPORT RecordingError : std::invalid_argument {
    std::size_t offset; ///< byte offset in the recording of the offending field
    std::string field;  ///< the field, e.g. "header.magic" or "records[3].body.position"
    std::string rule;   ///< what it breaks

    /// The error at byte `offset_` of field `field_`, which breaks `rule_`.
    RecordingError(std::size_t offset_, std::string field_, std::string rule_);
};

} // namespace tamias2d
