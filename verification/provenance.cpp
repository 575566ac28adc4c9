#include "provenance.hpp"

#include <fstream>

#include <nlohmann/json.hpp>

namespace tamias2d::evidence {

BuildProvenance build_provenance() {
    BuildProvenance b{"unknown", false, "", "", ""};
    std::ifstream in(TAMIAS_PROVENANCE_JSON);
    if (!in)
        return b;
    const nlohmann::json j = nlohmann::json::parse(in, nullptr, false);
    if (j.is_discarded() || !j.is_object())
        return b;
    b.commit = j.value("commit", "unknown");
    b.dirty = j.value("dirty", false);
    b.tree = j.value("tree", "");
    b.build_id = j.value("build_id", "");
    b.built = j.value("built", "");
    return b;
}

} // namespace tamias2d::evidence
