#pragma once
// RINEX 2 GPS observation types as RINEX 3 codes, so that observables read from either version
// can be looked up by meaning ("the L1 C/A pseudorange" is C1C in both). Ground side.
//
// RINEX 2.11 (Table A1 and section 10.1.1) names an observable by 2 characters: the kind (C
// C/A or L2C pseudorange, P P-code pseudorange, L phase, D Doppler, S signal strength) and the
// GPS band (1 L1, 2 L2, 5 L5); it does not say how the receiver tracked the signal. RINEX 3.05
// (section 5.1 "Observation codes", its GPS table) adds that as a third character: C C/A, W
// Z-tracking and similar (P(Y) under anti-spoofing), X the sum of two channels (L2C M+L, L5
// I+Q). There is no normative conversion table; the mapping chosen here, for GPS only:
//
//   C1 -> C1C   L1 -> L1C   D1 -> D1C   S1 -> S1C   the L1 C/A tracking (C1 is C/A by definition;
//                                                    the L1 phase, Doppler and SNR of geodetic
//                                                    receivers come from it)
//   P1 -> C1W                                       P code on L1: encrypted since anti-spoofing
//                                                    (31 Jan 1994), so P1 from a real receiver is
//                                                    Z-tracking (W); P from AS-off data would be
//                                                    C1P, which RINEX 2 cannot tell apart
//   P2 -> C2W   L2 -> L2W   D2 -> D2W   S2 -> S2W   the L2 P(Y) tracking: the only L2 signal before
//                                                    the first L2C satellite (IIR-M, launched
//                                                    September 2005) and what dual-frequency
//                                                    receivers report beside P2; RINEX 2.11
//                                                    section 7 says observations under AS are
//                                                    written as "L2"/"P2" (LLI bit 2)
//   C2 -> C2X                                       the L2C pseudorange (RINEX 2.11 section 0.6,
//                                                    "Observation code for L2C pseudorange (C2)");
//                                                    its channel (M, L or both) is not recorded,
//                                                    X (M+L) is the common receiver mode
//   C5 -> C5X   L5 -> L5X   D5 -> D5X   S5 -> S5X   L5, channel (I, Q or both) not recorded: X
//
// Caveats: a receiver that tracks L2C may write its L2 phase from that tracking (a quarter-cycle
// offset from L2W for the same satellite); the 2-character code cannot show it, so L2 -> L2W is a
// convention, as is X for the unrecorded channels. Check the receiver when it matters.

#include <optional>
#include <string>
#include <string_view>

namespace visors::gnss::files {

/// The RINEX 3 code of a RINEX 2 GPS observation type (table above), or nullopt for a code that
/// is not a GPS observable of RINEX 2.11 (Galileo-only bands 6, 7, 8, Transit T1/T2, P5,
/// lower-case or malformed codes).
std::optional<std::string> rinex2_gps_observation_code(std::string_view rinex2_code);

}  // namespace visors::gnss::files
