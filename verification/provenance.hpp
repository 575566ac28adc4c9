// What a verification program's results are of: the commit and build it was compiled from
// (written at build time by cmake/TamiasProvenance.cmake) and when it ran. The report refuses
// results whose commit or build id differ from the checkout's and the build's.
#pragma once

namespace tamias2d::evidence {

struct BuildProvenance {
    const char* commit;   ///< git HEAD at build time ("unknown" without git)
    bool dirty;           ///< the working tree had uncommitted changes to tracked files
    const char* build_id; ///< changes whenever the commit or those changes do
    const char* built;    ///< UTC time the build id was made
};

BuildProvenance build_provenance();

} // namespace tamias2d::evidence
