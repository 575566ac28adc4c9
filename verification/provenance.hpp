// What a verification program's results are of: the build it belongs to, as the build's last
// step recorded it in <build>/provenance.json (cmake/TamiasProvenance.cmake), and when it ran.
// The report refuses results whose tree or build id differ from the checkout's and the build's.
#pragma once

#include <string>

namespace tamias2d::evidence {

struct BuildProvenance {
    std::string commit;   ///< git HEAD at build time ("unknown" without git or a stamp)
    bool dirty = false;   ///< the working tree had uncommitted changes to tracked files
    std::string tree;     ///< the sources built: commit and uncommitted changes, hashed
    std::string build_id; ///< tree, compiler, flags, options and packages, hashed
    std::string built;    ///< UTC time the build id was first stamped
};

/// The build's provenance; commit "unknown" and an empty build id when the build has not
/// completed (no provenance.json yet), which the report refuses.
BuildProvenance build_provenance();

} // namespace tamias2d::evidence
