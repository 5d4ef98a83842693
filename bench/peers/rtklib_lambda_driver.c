/* Times RTKLIB's lambda() (m = 2) on the instances written by visors_export_ambiguity_instances:
 * 40 sweeps over the 50 instances of each family and size, median and worst per call, and the
 * instances whose search hit RTKLIB's loop cap (lambda() returning non-zero).
 * Built and run by scripts/bench_rtklib_lambda.sh against an RTKLIB source tree (not part of this
 * repository). Usage: rtklib_lambda_driver FILE */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

#include "rtklib.h"

#define FAMILIES 2
#define SIZES 3
#define INSTANCES 50
#define SWEEPS 40

static double a_all[FAMILIES * SIZES][INSTANCES][24];
static double q_all[FAMILIES * SIZES][INSTANCES][24 * 24];
static int n_all[FAMILIES * SIZES];
static double times_us[INSTANCES * SWEEPS];

static int ascending(const void *x, const void *y) {
  const double a = *(const double *)x, b = *(const double *)y;
  return (a > b) - (a < b);
}

static int read_instances(const char *path) {
  FILE *f = fopen(path, "rb");
  if (!f) return 0;
  for (int g = 0; g < FAMILIES * SIZES; ++g) {
    for (int k = 0; k < INSTANCES; ++k) {
      int32_t header[2];
      if (fread(header, sizeof header, 1, f) != 1 || header[1] < 1 || header[1] > 24) return fclose(f), 0;
      const int n = header[1];
      n_all[g] = n;
      if (fread(a_all[g][k], sizeof(double), (size_t)n, f) != (size_t)n) return fclose(f), 0;
      if (fread(q_all[g][k], sizeof(double), (size_t)(n * n), f) != (size_t)(n * n)) return fclose(f), 0;
    }
  }
  fclose(f);
  return 1;
}

int main(int argc, char **argv) {
  if (argc != 2 || !read_instances(argv[1])) {
    fprintf(stderr, "usage: %s INSTANCES_FILE (from visors_export_ambiguity_instances)\n", argv[0]);
    return 2;
  }
  for (int g = 0; g < FAMILIES * SIZES; ++g) {
    const int n = n_all[g];
    int count = 0, failures = 0;
    for (int sweep = 0; sweep < SWEEPS; ++sweep) {
      for (int k = 0; k < INSTANCES; ++k) {
        double F[24 * 2], s[2];
        struct timespec t0, t1;
        clock_gettime(CLOCK_MONOTONIC, &t0);
        const int status = lambda(n, 2, a_all[g][k], q_all[g][k], F, s);
        clock_gettime(CLOCK_MONOTONIC, &t1);
        times_us[count++] = (double)(t1.tv_sec - t0.tv_sec) * 1e6 + (double)(t1.tv_nsec - t0.tv_nsec) * 1e-3;
        if (status != 0 && sweep == 0) ++failures;
      }
    }
    qsort(times_us, (size_t)count, sizeof(double), ascending);
    printf("rtklib lambda  %-10s n=%2d  median_us=%.1f  worst_us=%.1f  failures=%d/%d\n", g < SIZES ? "dd" : "random_spd",
           n, times_us[count / 2], times_us[count - 1], failures, INSTANCES);
  }
  return 0;
}
