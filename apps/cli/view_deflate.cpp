// DEFLATE (RFC 1951), literals only: dynamic Huffman blocks, one code per block.
#include "view_deflate.hpp"

#include <algorithm>
#include <array>
#include <cstddef>
#include <queue>
#include <tuple>

namespace tamias2d::cli {
namespace {

/// Each block gets its own code, so that the code follows the data (a run's frames change
/// character as bodies fall and settle).
constexpr std::size_t block_size = std::size_t{1} << 18;

/// Bits into bytes, least significant bit first (RFC 1951, 3.1.1).
class BitWriter {
  public:
    void put(std::uint32_t bits, int count) {
        acc_ |= static_cast<std::uint64_t>(bits) << filled_;
        filled_ += count;
        while (filled_ >= 8) {
            bytes_.push_back(static_cast<std::uint8_t>(acc_ & 0xFF));
            acc_ >>= 8;
            filled_ -= 8;
        }
    }
    /// A Huffman code goes most significant bit first.
    void put_code(std::uint32_t code, int length) {
        std::uint32_t reversed = 0;
        for (int i = 0; i < length; ++i)
            reversed |= ((code >> i) & 1U) << (length - 1 - i);
        put(reversed, length);
    }
    std::vector<std::uint8_t> finish() {
        if (filled_ > 0)
            bytes_.push_back(static_cast<std::uint8_t>(acc_ & 0xFF));
        acc_ = 0;
        filled_ = 0;
        return std::move(bytes_);
    }

  private:
    std::vector<std::uint8_t> bytes_;
    std::uint64_t acc_ = 0;
    int filled_ = 0;
};

/// Huffman code lengths of the symbols with non-zero frequency (0 for the others).
std::vector<int> huffman_lengths(const std::vector<std::uint64_t>& freq) {
    const std::size_t n = freq.size();
    std::vector<int> parent(2 * n, -1);
    // (weight, node): ties broken by node number, so that the code is reproducible.
    using Entry = std::tuple<std::uint64_t, std::size_t>;
    std::priority_queue<Entry, std::vector<Entry>, std::greater<>> queue;
    for (std::size_t s = 0; s < n; ++s)
        if (freq[s] > 0)
            queue.emplace(freq[s], s);
    std::size_t next = n;
    while (queue.size() > 1) {
        const auto [wa, a] = queue.top();
        queue.pop();
        const auto [wb, b] = queue.top();
        queue.pop();
        parent[a] = parent[b] = static_cast<int>(next);
        queue.emplace(wa + wb, next++);
    }
    std::vector<int> lengths(n, 0);
    for (std::size_t s = 0; s < n; ++s) {
        if (freq[s] == 0)
            continue;
        for (int p = parent[s]; p >= 0; p = parent[static_cast<std::size_t>(p)])
            ++lengths[s];
    }
    return lengths;
}

/// Code lengths no longer than `limit`: frequencies are flattened (halved, rounding up) until
/// the Huffman tree is shallow enough. At least two symbols get a code, so that the code is
/// complete, as inflaters require.
std::vector<int> limited_lengths(std::vector<std::uint64_t> freq, int limit) {
    std::size_t used = 0;
    for (std::uint64_t f : freq)
        used += f > 0 ? 1 : 0;
    for (std::size_t s = 0; used < 2 && s < freq.size(); ++s)
        if (freq[s] == 0) {
            freq[s] = 1;
            ++used;
        }
    while (true) {
        std::vector<int> lengths = huffman_lengths(freq);
        if (*std::max_element(lengths.begin(), lengths.end()) <= limit)
            return lengths;
        for (std::uint64_t& f : freq)
            f = (f + 1) / 2;
    }
}

/// Canonical codes for the lengths (RFC 1951, 3.2.2).
std::vector<std::uint32_t> canonical_codes(const std::vector<int>& lengths) {
    std::array<std::uint32_t, 16> count{};
    for (const int l : lengths)
        if (l > 0)
            ++count[static_cast<std::size_t>(l)];
    std::array<std::uint32_t, 16> next{};
    std::uint32_t code = 0;
    for (std::size_t bits = 1; bits < 16; ++bits) {
        code = (code + count[bits - 1]) << 1;
        next[bits] = code;
    }
    std::vector<std::uint32_t> codes(lengths.size(), 0);
    for (std::size_t s = 0; s < lengths.size(); ++s)
        if (lengths[s] > 0)
            codes[s] = next[static_cast<std::size_t>(lengths[s])]++;
    return codes;
}

void write_block(BitWriter& out, std::span<const std::uint8_t> data, bool final) {
    constexpr std::size_t end_of_block = 256;
    std::vector<std::uint64_t> freq(257, 0);
    for (const std::uint8_t b : data)
        ++freq[b];
    freq[end_of_block] = 1;
    const std::vector<int> lit = limited_lengths(freq, 15);
    // One distance code of one bit: no distance is ever coded (RFC 1951, 3.2.7).
    std::vector<int> lengths = lit;
    lengths.push_back(1);

    // The code lengths are themselves Huffman-coded (symbols 0 to 15 only: no repeats).
    std::vector<std::uint64_t> cl_freq(19, 0);
    for (const int l : lengths)
        ++cl_freq[static_cast<std::size_t>(l)];
    const std::vector<int> cl = limited_lengths(cl_freq, 7);
    static constexpr std::array<std::size_t, 19> order = {16, 17, 18, 0, 8,  7, 9,  6, 10, 5,
                                                          11, 4,  12, 3, 13, 2, 14, 1, 15};
    std::size_t hclen = order.size();
    while (hclen > 4 && cl[order[hclen - 1]] == 0)
        --hclen;

    out.put(final ? 1U : 0U, 1);
    out.put(2, 2); // dynamic Huffman codes
    out.put(0, 5); // HLIT: 257 literal/length codes
    out.put(0, 5); // HDIST: 1 distance code
    out.put(static_cast<std::uint32_t>(hclen - 4), 4);
    for (std::size_t i = 0; i < hclen; ++i)
        out.put(static_cast<std::uint32_t>(cl[order[i]]), 3);
    const std::vector<std::uint32_t> cl_codes = canonical_codes(cl);
    for (const int l : lengths)
        out.put_code(cl_codes[static_cast<std::size_t>(l)], cl[static_cast<std::size_t>(l)]);
    const std::vector<std::uint32_t> codes = canonical_codes(lit);
    for (const std::uint8_t b : data)
        out.put_code(codes[b], lit[b]);
    out.put_code(codes[end_of_block], lit[end_of_block]);
}

} // namespace

std::vector<std::uint8_t> deflate_literals(std::span<const std::uint8_t> data) {
    BitWriter out;
    std::size_t at = 0;
    do {
        const std::size_t n = std::min(block_size, data.size() - at);
        write_block(out, data.subspan(at, n), at + n == data.size());
        at += n;
    } while (at < data.size());
    return out.finish();
}

} // namespace tamias2d::cli
