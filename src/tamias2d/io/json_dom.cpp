#include "json_dom.hpp"

#include <algorithm>
#include <unordered_set>
#include <utility>
#include <vector>

#include "tamias2d/io/scene.hpp"

namespace tamias2d::io::scene_detail {

std::string printable(std::string_view s, std::size_t max) {
    std::string out;
    std::size_t kept = 0;
    for (; kept < s.size() && out.size() < max; ++kept) {
        const auto c = static_cast<unsigned char>(s[kept]);
        if (c == '\n') {
            out += "\\n";
        } else if (c == '\r') {
            out += "\\r";
        } else if (c == '\t') {
            out += "\\t";
        } else if (c < 0x20 || c == 0x7f) {
            static constexpr char hex[] = "0123456789abcdef";
            out += "\\u00";
            out += hex[c >> 4];
            out += hex[c & 15];
        } else {
            out += static_cast<char>(c);
        }
    }
    while (kept < s.size() && kept > 0 && (static_cast<unsigned char>(s[kept]) & 0xc0) == 0x80) {
        --kept; // not inside a UTF-8 sequence
        out.pop_back();
    }
    if (kept < s.size())
        out += "... (" + std::to_string(s.size()) + " bytes)";
    return out;
}

std::string shown_pointer(std::string_view pointer) {
    constexpr std::size_t token_max = 32, keep = 6;
    std::vector<std::string> tokens;
    for (std::size_t start = 1; start <= pointer.size();) {
        std::size_t end = pointer.find('/', start);
        if (end == std::string_view::npos)
            end = pointer.size();
        tokens.push_back(printable(pointer.substr(start, end - start), token_max));
        start = end + 1;
    }
    std::string out;
    for (std::size_t i = 0; i < tokens.size(); ++i) {
        if (tokens.size() > 2 * keep && i == keep) {
            out += "/[... " + std::to_string(tokens.size() - 2 * keep) + " levels ...]";
            i = tokens.size() - keep - 1;
            continue;
        }
        out += "/" + tokens[i];
    }
    return out;
}

std::string quote(std::string_view s) {
    std::string out = "'"; // (appended, not "'" + ...: GCC 12 warns falsely of an overlap there)
    out += printable(s, 64);
    out += '\'';
    return out;
}

std::string escape_token(std::string_view key) {
    std::string out;
    for (const char c : key) {
        if (c == '~')
            out += "~0";
        else if (c == '/')
            out += "~1";
        else
            out += c;
    }
    return out;
}

ojson& append_member(ojson& object, std::string key, ojson value) {
    // The ordered object is a vector of members: appended in place, without the linear search
    // of operator[] or emplace.
    ojson::object_t& members = object.get_ref<ojson::object_t&>();
    members.emplace_back(std::move(key), std::move(value));
    return members.back().second;
}

namespace {

// ---------------------------------------------------------------------------------------------
// JSON text -> DOM, with positions for syntax errors and detection of duplicate keys
// ---------------------------------------------------------------------------------------------

class DomBuilder {
  public:
    using number_integer_t = ojson::number_integer_t;
    using number_unsigned_t = ojson::number_unsigned_t;
    using number_float_t = ojson::number_float_t;
    using string_t = ojson::string_t;
    using binary_t = ojson::binary_t;

    static constexpr std::size_t max_depth = 128;

    ojson root;
    // Failure report.
    bool failed = false;
    std::size_t position = 0; // chars read when a syntax error happened (0: no position)
    std::string message;
    std::string pointer;    // for duplicate keys and nesting
    std::string last_token; // the token the parser stopped at

    bool null() { return put(nullptr); }
    bool boolean(bool b) { return put(b); }
    bool number_integer(number_integer_t v) { return put(v); }
    bool number_unsigned(number_unsigned_t v) { return put(v); }
    bool number_float(number_float_t v, const string_t&) { return put(v); }
    bool string(string_t& s) { return put(s); }
    bool binary(binary_t&) { return error_at_pointer("binary values are not JSON"); }
    bool start_object(std::size_t) { return open(ojson::object()); }
    bool start_array(std::size_t) { return open(ojson::array()); }
    bool end_object() { return close(); }
    bool end_array() { return close(); }
    bool key(string_t& k) {
        if (!keys_.back().insert(k).second) {
            pointer = current_pointer() + "/" + escape_token(k);
            return error_at_pointer("duplicate key " + quote(k));
        }
        key_ = k;
        return true;
    }
    bool parse_error(std::size_t pos, const std::string& token,
                     const nlohmann::detail::exception& e) {
        failed = true;
        position = pos;
        last_token = token;
        std::string what = e.what();
        const auto syntax = what.find("syntax error");
        if (syntax != std::string::npos) {
            what.erase(0, syntax);
        } else if (const auto close = what.find("] "); close != std::string::npos) {
            what.erase(0, close + 2);
        }
        // The parser quotes the whole token it stopped in ("last read: '...'"), which may be a
        // string of megabytes: keep its start.
        if (const auto lr = what.find("last read: '"); lr != std::string::npos) {
            const std::size_t start = lr + 12;
            std::size_t end = what.find("'; expected", start);
            if (end == std::string::npos)
                end = what.rfind('\'');
            if (end != std::string::npos && end > start)
                what.replace(start, end - start, printable(what.substr(start, end - start), 40));
        }
        if (what.starts_with("number overflow"))
            what += " (DCX_finite)";
        message = what;
        return false;
    }

  private:
    std::vector<ojson*> stack_;
    // The keys of each open container so far (none for an array): a duplicate is found in
    // constant expected time, where the ordered object's own lookup is linear in its keys.
    std::vector<std::unordered_set<std::string>> keys_;
    std::vector<std::string> path_;
    std::string key_;

    std::string segment() const {
        if (stack_.empty())
            return {};
        return stack_.back()->is_array() ? std::to_string(stack_.back()->size())
                                         : escape_token(key_);
    }
    std::string current_pointer() const {
        std::string p;
        for (const std::string& s : path_)
            p += "/" + s;
        return p;
    }
    template <class V> ojson* insert(V&& v) {
        if (stack_.empty()) {
            root = std::forward<V>(v);
            return &root;
        }
        ojson& top = *stack_.back();
        if (top.is_array()) {
            top.push_back(std::forward<V>(v));
            return &top.back();
        }
        return &append_member(top, key_, ojson(std::forward<V>(v))); // key() found it new
    }
    template <class V> bool put(V&& v) {
        insert(std::forward<V>(v));
        return true;
    }
    bool open(ojson container) {
        if (stack_.size() >= max_depth) {
            pointer = current_pointer();
            return error_at_pointer("nesting deeper than " + std::to_string(max_depth) + " levels");
        }
        std::string seg = segment();
        ojson* p = insert(std::move(container));
        if (!stack_.empty())
            path_.push_back(std::move(seg));
        stack_.push_back(p);
        keys_.emplace_back();
        return true;
    }
    bool close() {
        stack_.pop_back();
        keys_.pop_back();
        if (!path_.empty()) // the root has no segment
            path_.pop_back();
        return true;
    }
    bool error_at_pointer(std::string msg) {
        failed = true;
        message = std::move(msg);
        return false;
    }
};

/// 1-based line and column of the byte at `at`.
std::pair<int, int> line_column(std::string_view text, std::size_t at) {
    const auto nl_before = text.substr(0, at).rfind('\n');
    const int line = 1 + static_cast<int>(std::count(text.begin(), text.begin() + at, '\n'));
    const int column =
        static_cast<int>(nl_before == std::string_view::npos ? at + 1 : at - nl_before);
    return {line, column};
}

} // namespace

ojson parse_json(std::string_view text, const std::string& origin) {
    // The parser takes a NUL byte for the end of the input, so that a scene followed by one and
    // garbage would load. JSON text has no NUL (in a string it must be escaped): reject it.
    if (const auto nul = text.find('\0'); nul != std::string_view::npos) {
        const auto [line, column] = line_column(text, nul);
        throw SceneError(origin, "", line, column, "", "",
                         "syntax error: a NUL byte (JSON text has none)");
    }
    DomBuilder dom;
    const bool ok = ojson::sax_parse(text.begin(), text.end(), &dom);
    if (ok && !dom.failed)
        return std::move(dom.root);
    if (dom.position > 0) {
        // Line and column (1-based) of the character at which the parser stopped, or of the
        // end of the input. For an unexpected string or an overflowing number the parser has
        // read the whole token: point at its start instead.
        std::size_t at = std::min(dom.position - 1, text.size());
        const std::string& tok = dom.last_token;
        const bool whole_token = (tok.size() >= 2 && tok.front() == '"' && tok.back() == '"') ||
                                 dom.message.starts_with("number overflow");
        if (whole_token && tok.size() <= dom.position && dom.position <= text.size() &&
            text.substr(dom.position - tok.size(), tok.size()) == tok)
            at = dom.position - tok.size();
        const auto [line, column] = line_column(text, at);
        throw SceneError(origin, "", line, column, "",
                         dom.message.ends_with("(DCX_finite)") ? "DCX_finite" : "", dom.message);
    }
    throw SceneError(origin, dom.pointer, 0, 0, "", "", dom.message);
}

} // namespace tamias2d::io::scene_detail
