/// \file
/// The error a snapshot that cannot be read is refused with (World::from_snapshot,
/// World::restore).
#pragma once

#include <cstddef>
#include <stdexcept>
#include <string>

#include "tamias2d/export.hpp"

namespace tamias2d {

/// A snapshot was refused: it is not one (a foreign file: wrong magic), of a format this library
/// does not read (format version), cut short (truncated), changed since it was written (the
/// checksum disagrees), or its contents break a rule of the world they describe (an index out of
/// range, a count beyond the bytes left, a flag that is neither 0 nor 1). Nothing was changed:
/// World::restore leaves the world exactly as it was.
struct TAMIAS2D_EXPORT SnapshotError : std::invalid_argument {
    std::size_t offset; ///< byte offset in the snapshot of the offending field
    std::string field;  ///< the field, e.g. "header.magic" or "bodies[3].first_shape"
    std::string rule;   ///< what it breaks, e.g. "must be < 12 (the shape count)"

    /// what(): "snapshot refused at byte 40, bodies[3].first_shape: must be < 12 (...)".
    SnapshotError(std::size_t offset_, std::string field_, std::string rule_);
};

} // namespace tamias2d
