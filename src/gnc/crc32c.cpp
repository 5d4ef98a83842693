#include "gnc/crc32c.hpp"

#include <array>

namespace visors::gnc {
namespace {

constexpr std::uint32_t kReflectedPolynomial = 0x82F63B78u;

// The remainder of each byte value, shifted through the polynomial bit by bit (the usual
// reflected table of a CRC).
constexpr std::array<std::uint32_t, 256> make_table() {
  std::array<std::uint32_t, 256> table{};
  for (std::uint32_t byte = 0; byte < 256; ++byte) {
    std::uint32_t r = byte;
    for (int bit = 0; bit < 8; ++bit) r = (r & 1u) != 0 ? (r >> 1) ^ kReflectedPolynomial : r >> 1;
    table[byte] = r;
  }
  return table;
}

constexpr std::array<std::uint32_t, 256> kTable = make_table();

}  // namespace

std::uint32_t crc32c(std::span<const std::uint8_t> bytes) {
  std::uint32_t crc = 0xFFFFFFFFu;
  for (const std::uint8_t b : bytes) crc = kTable[(crc ^ b) & 0xFFu] ^ (crc >> 8);
  return crc ^ 0xFFFFFFFFu;
}

}  // namespace visors::gnc
