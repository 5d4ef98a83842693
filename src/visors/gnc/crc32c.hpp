#pragma once
// CRC-32C (Castagnoli; iSCSI, RFC 3720 sec. 12.1 and B.4): the checksum of the flight
// component's binary records (gnc/channel_record.hpp). Chosen over CRC-16-CCITT for its Hamming
// distance at the records' lengths (Castagnoli, Braeuer & Herrmann 1993; Koopman's CRC tables:
// HD 6 up to 5,243 data bits): every error of up to 5 bits in a record of up to 655 bytes is
// detected, every burst of up to 32 bits at any length, and a random record passes with
// probability 2^-32 (CRC-16: HD 4 at these lengths, 2^-16). Table-driven, reflected polynomial 0x82F63B78, initial value and final XOR 0xFFFFFFFF;
// check value of the ASCII "123456789": 0xE3069283. No allocation, no exception.

#include <cstdint>
#include <span>

namespace visors::gnc {

/// The CRC-32C of `bytes`.
[[nodiscard]] std::uint32_t crc32c(std::span<const std::uint8_t> bytes);

}  // namespace visors::gnc
