// A small DEFLATE encoder (RFC 1951) for the player's data: browsers inflate it natively
// (DecompressionStream("deflate-raw")), so the page needs no decompressor of its own.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

namespace tamias2d::cli {

/// `data` as a raw DEFLATE stream of dynamic-Huffman blocks holding literals only. The
/// player's streams are residuals without long repeats (LZ77 gains under 1 % on them), but
/// their bytes are far from uniform: Huffman coding alone saves about 40 %.
std::vector<std::uint8_t> deflate_literals(std::span<const std::uint8_t> data);

} // namespace tamias2d::cli
