#include "tamias2d/snapshot_error.hpp"

#include <string>
#include <utility>

namespace tamias2d {

// Defined here, not inline in the header: the message's number formatting stays inside the
// library instead of being exported with the class.
SnapshotError::SnapshotError(std::size_t offset_, std::string field_, std::string rule_)
    : std::invalid_argument("snapshot refused at byte " + std::to_string(offset_) + ", " + field_ +
                            ": " + rule_),
      offset(offset_), field(std::move(field_)), rule(std::move(rule_)) {}

} // namespace tamias2d
