// What every verification program writes: a list of checks (name, SRS labels, passed, oracle,
// details, optionally a target), tables and plot series, as one JSON document in
// <out_dir>/<program>.json (schema: docs/traceability.md). Shared so that the schema is written
// in one place.
#pragma once

#include <cstdio>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "provenance.hpp"

namespace tamias2d::evidence {

/// The "provenance" object of a results file: the build's commit and id, and the time now
/// (UTC), so that the report can refuse results left over from another commit or build.
inline nlohmann::json provenance() {
    const BuildProvenance b = build_provenance();
    char now[32];
    const std::time_t t = std::time(nullptr);
    std::strftime(now, sizeof now, "%Y-%m-%dT%H:%M:%SZ", std::gmtime(&t));
    return {{"commit", b.commit},     {"dirty", b.dirty}, {"tree", b.tree},
            {"build_id", b.build_id}, {"built", b.built}, {"generated", now}};
}

/// A number for a details text: `prec` significant digits.
inline std::string fmt(double v, int prec = 3) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.*g", prec, v);
    return buf;
}

/// One check object. A non-empty `target` marks a goal beyond the SRS: the report lists it met
/// or missed, apart from the checks that verify SRS items.
template <class Json>
Json check_entry(std::string name, std::vector<std::string> labels, bool passed, std::string oracle,
                 std::string details, const std::string& target = {}) {
    Json c = {{"name", std::move(name)},
              {"labels", std::move(labels)},
              {"passed", passed},
              {"oracle", std::move(oracle)},
              {"details", std::move(details)}};
    if (!target.empty())
        c["target"] = target;
    return c;
}

/// Checks, tables and series of one program, printed as they are added.
struct Report {
    using json = nlohmann::json;
    json checks = json::array();
    json tables = json::array();
    json series = json::array();
    int failures = 0;

    void check(std::string name, std::vector<std::string> labels, bool passed, std::string oracle,
               std::string details) {
        failures += passed ? 0 : 1;
        std::cout << (passed ? "ok   " : "FAIL ") << name << ": " << details << "\n";
        checks.push_back(check_entry<json>(std::move(name), std::move(labels), passed,
                                           std::move(oracle), std::move(details)));
    }

    /// Writes <out_dir>/<program>.json; the exit status: 0 when every check passed.
    int write(const std::filesystem::path& out_dir, const std::string& program,
              const std::string& description) const {
        const json doc = {{"program", program},         {"description", description},
                          {"provenance", provenance()}, {"checks", checks},
                          {"tables", tables},           {"series", series}};
        std::filesystem::create_directories(out_dir);
        const std::filesystem::path file = out_dir / (program + ".json");
        std::ofstream(file) << doc.dump(2) << "\n";
        std::cout << checks.size() << " checks, " << failures << " failed; wrote " << file.string()
                  << "\n";
        return failures == 0 ? 0 : 1;
    }
};

} // namespace tamias2d::evidence
