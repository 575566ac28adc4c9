// What the benchmark programs (tamias_bench, tamias_work_precision) write beside their figures,
// in one place: medians and quantiles of repeated timings, figures rounded for the JSON, the
// machine and its load, and log-log plots.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <fstream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

namespace tamias_bench {

/// The items of a comma-separated command-line list (--scenes a,b), empty ones left out.
inline std::vector<std::string> split(const std::string& s) {
    std::vector<std::string> out;
    std::stringstream ss(s);
    for (std::string item; std::getline(ss, item, ',');) {
        if (!item.empty())
            out.push_back(item);
    }
    return out;
}

inline double median(std::vector<double> v) {
    if (v.empty())
        return NAN;
    std::sort(v.begin(), v.end());
    const std::size_t n = v.size();
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

/// The q-quantile by linear interpolation between order statistics (q in [0, 1]).
inline double quantile(std::vector<double> v, double q) {
    if (v.empty())
        return NAN;
    std::sort(v.begin(), v.end());
    const double at = q * double(v.size() - 1);
    const std::size_t lo = std::size_t(at);
    const std::size_t hi = std::min(lo + 1, v.size() - 1);
    return v[lo] + (at - double(lo)) * (v[hi] - v[lo]);
}

/// `v` to `digits` significant digits for the JSON; null when it is not finite.
inline nlohmann::ordered_json num(double v, int digits = 4) {
    if (!std::isfinite(v))
        return nullptr;
    const double scale = std::pow(10.0, digits - 1 - std::floor(std::log10(std::abs(v) + 1e-300)));
    return std::round(v * scale) / scale;
}

inline std::string cpu_model() {
    std::ifstream in("/proc/cpuinfo");
    for (std::string line; std::getline(in, line);) {
        if (line.rfind("model name", 0) == 0)
            return line.substr(line.find(':') + 2);
    }
    return "unknown";
}

/// The load averages over 1, 5 and 15 minutes (/proc/loadavg).
inline std::string load_average() {
    std::ifstream in("/proc/loadavg");
    std::string a, b, c;
    in >> a >> b >> c;
    return a + " " + b + " " + c;
}

/// A plot for the report, both axes logarithmic.
inline nlohmann::ordered_json log_log_series(const std::string& name, const std::string& x_label,
                                             const std::string& y_label,
                                             nlohmann::ordered_json lines) {
    return {{"name", name},  {"x_label", x_label}, {"y_label", y_label},
            {"log_x", true}, {"log_y", true},      {"lines", std::move(lines)}};
}

} // namespace tamias_bench
