// Writes the IAR benchmark's instances (ambiguity_instances.hpp) for peer implementations: for
// each family (0: DD geometry, 1: random SPD) and n in 8, 16, 24, 50 records of
// int32 family, int32 n, n doubles a [cycles], n x n doubles Q column-major [cycles^2].
// Usage: visors_export_ambiguity_instances FILE
#include <cstdint>
#include <cstdio>

#include "ambiguity_instances.hpp"

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: %s FILE\n", argv[0]);
    return 2;
  }
  std::FILE* f = std::fopen(argv[1], "wb");
  if (f == nullptr) {
    std::fprintf(stderr, "cannot write %s\n", argv[1]);
    return 2;
  }
  for (std::int32_t family = 0; family < 2; ++family) {
    for (std::int32_t n : {8, 16, 24}) {
      const auto instances = family == 0 ? visors::bench::dd_family(n) : visors::bench::random_spd_family(n);
      for (const auto& inst : instances) {
        const std::int32_t header[2] = {family, n};
        std::fwrite(header, sizeof header, 1, f);
        std::fwrite(inst.a.data(), sizeof(double), static_cast<std::size_t>(n), f);
        std::fwrite(inst.Q.data(), sizeof(double), static_cast<std::size_t>(n) * static_cast<std::size_t>(n), f);
      }
    }
  }
  return std::fclose(f) == 0 ? 0 : 2;
}
