#include "tamias2d/snapshot_error.hpp"

#include <string>
#include <utility>

#include "tamias2d/dynamics/snapshot_io.hpp"

namespace tamias2d {

// Defined here, not inline in the header, and with decimal() rather than std::to_string: no
// standard library template is instantiated out of line and exported from the shared library.
SnapshotError::SnapshotError(std::size_t offset_, std::string field_, std::string rule_)
    : std::invalid_argument("snapshot refused at byte " + decimal(std::uint64_t(offset_)) + ", " +
                            field_ + ": " + rule_),
      offset(offset_), field(std::move(field_)), rule(std::move(rule_)) {}

} // namespace tamias2d
