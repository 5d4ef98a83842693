#pragma once
// Fixed capacity of the integer ambiguity resolution: every matrix of the nav layer's ambiguity
// code is an Eigen matrix with a compile-time maximum size, so resizing within the capacity never
// touches the heap (Eigen stores such matrices inline) and a step allocates nothing.
//
// 64 ambiguities cover 32 satellites on two frequencies, or the navigation filter's 24
// single-difference slots with room to spare; 16 candidates is far more than acceptance tests use
// (2 for the ratio test).

#include <Eigen/Core>

namespace visors::nav {

inline constexpr int kMaxAmbiguities = 64;
inline constexpr int kMaxCandidates = 16;

/// n x n matrix, n <= kMaxAmbiguities, stored inline (no heap).
using AmbiguityMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::ColMajor, kMaxAmbiguities, kMaxAmbiguities>;
/// n-vector, n <= kMaxAmbiguities, stored inline.
using AmbiguityVector = Eigen::Matrix<double, Eigen::Dynamic, 1, Eigen::ColMajor, kMaxAmbiguities, 1>;
/// n x m candidate integer vectors (columns), exact integers held in doubles (|z| < 2^53).
using CandidateMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::ColMajor, kMaxAmbiguities, kMaxCandidates>;
/// m values, m <= kMaxCandidates.
using CandidateVector = Eigen::Matrix<double, Eigen::Dynamic, 1, Eigen::ColMajor, kMaxCandidates, 1>;

}  // namespace visors::nav
