#include "visors/dynamics/nrlmsise00_expansion.hpp"

#include <cmath>

namespace visors::dynamics::nrlmsise00_detail {
namespace {

// The indices of the phase constants of a full table, per mode (FullPhaseTerms' order): local
// time of the geomagnetic diurnal term, UT, UT-longitude, the two geomagnetic longitude terms,
// geomagnetic UT.
constexpr std::array<int, 6> kDailyPhaseIndex{124, 71, 79, 63, 118, 75};
constexpr std::array<int, 6> kHistoryPhaseIndex{131, 71, 79, 97, 136, 58};
// The scale of each phase: hours, seconds, seconds, degrees, degrees, seconds.
constexpr std::array<double, 6> kPhaseScale{kHour, kSecond, kSecond, kDegree, kDegree, kSecond};

std::size_t at(int i) { return static_cast<std::size_t>(i); }

// Hedin (1987) eq. A24d: the nonlinear ap scaling of the history mode.
double history_scaled_ap(double ap, const FullTable& p) {
  const double k = std::abs(p[24] < 1e-4 ? 1e-4 : p[24]);  // the published code raises p[24] to 1e-4
  return ap - 4.0 + (p[25] - 1.0) * (ap - 4.0 + (std::exp(-k * (ap - 4.0)) - 1.0) / k);
}

// Hedin (1987) eqs. A24a-c: the exponentially weighted ap history with decay e per 3 hours.
double weighted_ap_history(double e, const FullTable& p, const std::array<double, 7>& ap) {
  const double sum = 1.0 + (1.0 - std::pow(e, 19.0)) / (1.0 - e) * std::sqrt(e);
  return (history_scaled_ap(ap[1], p) +
          (history_scaled_ap(ap[2], p) * e + history_scaled_ap(ap[3], p) * e * e +
           history_scaled_ap(ap[4], p) * std::pow(e, 3.0) +
           (history_scaled_ap(ap[5], p) * std::pow(e, 4.0) + history_scaled_ap(ap[6], p) * std::pow(e, 12.0)) *
               (1.0 - std::pow(e, 8.0)) / (1.0 - e))) /
         sum;
}

}  // namespace

Basis make_basis(double latitude_deg, double longitude_deg, double lst_h, double ut_seconds, double f107a,
                 bool cached_path) {
  Basis b;
  b.latitude_deg = latitude_deg;
  b.longitude_deg = longitude_deg;
  b.lst_h = lst_h;
  b.ut_seconds = ut_seconds;
  b.dfa = f107a - 150.0;
  // Associated Legendre functions P_n^m(c), c = sin(latitude), s = cos(latitude) (closed forms
  // for the low degrees, then the recurrence (n - m + 1) P_{n+1}^m = (2n + 1) c P_n^m - (n + m) P_{n-1}^m).
  const double c = std::sin(latitude_deg * kDegree);
  const double s = std::cos(latitude_deg * kDegree);
  const double c2 = c * c;
  const double c4 = c2 * c2;
  const double s2 = s * s;
  auto& l = b.legendre;
  l[0][1] = c;
  l[0][2] = 0.5 * (3.0 * c2 - 1.0);
  l[0][3] = 0.5 * (5.0 * c * c2 - 3.0 * c);
  l[0][4] = (35.0 * c4 - 30.0 * c2 + 3.0) / 8.0;
  l[0][5] = (63.0 * c2 * c2 * c - 70.0 * c2 * c + 15.0 * c) / 8.0;
  l[0][6] = (11.0 * c * l[0][5] - 5.0 * l[0][4]) / 6.0;
  l[1][1] = s;
  l[1][2] = 3.0 * c * s;
  l[1][3] = 1.5 * (5.0 * c2 - 1.0) * s;
  l[1][4] = 2.5 * (7.0 * c2 * c - 3.0 * c) * s;
  l[1][5] = 1.875 * (21.0 * c4 - 14.0 * c2 + 1.0) * s;
  l[1][6] = (11.0 * c * l[1][5] - 6.0 * l[1][4]) / 5.0;
  l[2][2] = 3.0 * s2;
  l[2][3] = 15.0 * s2 * c;
  l[2][4] = 7.5 * (7.0 * c2 - 1.0) * s2;
  l[2][5] = 3.0 * c * l[2][4] - 2.0 * l[2][3];
  l[2][6] = (11.0 * c * l[2][5] - 7.0 * l[2][4]) / 4.0;
  l[2][7] = (13.0 * c * l[2][6] - 8.0 * l[2][5]) / 5.0;
  l[3][3] = 15.0 * s2 * s;
  l[3][4] = 105.0 * s2 * s * c;
  l[3][5] = (9.0 * c * l[3][4] - 7.0 * l[3][3]) / 2.0;
  l[3][6] = (11.0 * c * l[3][5] - 8.0 * l[3][4]) / 3.0;
  // Local-time harmonics (Hedin 1987 eq. A22: tau = kHour lst).
  b.sin_lt1 = std::sin(kHour * lst_h);
  b.cos_lt1 = std::cos(kHour * lst_h);
  if (cached_path) {
    const double cs = b.cos_lt1;
    const double sn = b.sin_lt1;
    b.cos_lt2 = cs * cs - sn * sn;
    b.sin_lt2 = 2.0 * sn * cs;
    b.cos_lt3 = cs * (cs * cs - 3.0 * sn * sn);
    b.sin_lt3 = sn * (3.0 * cs * cs - sn * sn);
  } else {
    b.sin_lt2 = std::sin(2.0 * kHour * lst_h);
    b.cos_lt2 = std::cos(2.0 * kHour * lst_h);
    b.sin_lt3 = std::sin(3.0 * kHour * lst_h);
    b.cos_lt3 = std::cos(3.0 * kHour * lst_h);
  }
  b.cos_lon = std::cos(kDegree * longitude_deg);
  b.sin_lon = std::sin(kDegree * longitude_deg);
  if (cached_path) {
    b.cos_ut = std::cos(kSecond * ut_seconds);
    b.sin_ut = std::sin(kSecond * ut_seconds);
    const double ut_lon = kSecond * ut_seconds + 2.0 * kDegree * longitude_deg;
    b.cos_ut_lon = std::cos(ut_lon);
    b.sin_ut_lon = std::sin(ut_lon);
  }
  return b;
}

namespace {

// The decay factor of the history mode (eq. A24a's "exp1"), capped as published.
double history_decay(const FullTable& p, double latitude_deg) {
  const double e = std::exp(-10800.0 * std::abs(p[51]) / (1.0 + p[138] * (45.0 - std::abs(latitude_deg))));
  return e > 0.99999 ? 0.99999 : e;
}

}  // namespace

double magnetic_function_cached(const FullTable& p, const FullDayTerms& day, double latitude_deg) {
  if (p[51] == 0.0) return 0.0;
  const double e = history_decay(p, latitude_deg);
  const auto& g = day.history_scaled;
  const double e2 = e * e;
  const double e3 = e2 * e;
  const double e4 = e2 * e2;
  const double e8 = e4 * e4;
  const double e12 = e8 * e4;
  const double e19 = e12 * e4 * e3;
  const double sum = 1.0 + (1.0 - e19) / (1.0 - e) * std::sqrt(e);
  return (g[0] + (g[1] * e + g[2] * e2 + g[3] * e3 + (g[4] * e4 + g[5] * e12) * (1.0 - e8) / (1.0 - e))) / sum;
}

double magnetic_function(const FullTable& p, const SolarActivity& activity, double latitude_deg) {
  if (!history_mode(activity)) {
    const double a = activity.ap - 4.0;
    const double p44 = p[43] < 0.0 ? 1e-5 : p[43];
    return a + (p[44] - 1.0) * (a + (std::exp(-p44 * a) - 1.0) / p44);
  }
  if (p[51] == 0.0) return 0.0;
  return weighted_ap_history(history_decay(p, latitude_deg), p, *activity.ap_history);
}

bool magnetic_depends_on_latitude(const FullTable& p, const SolarActivity& activity) {
  return history_mode(activity) && p[51] != 0.0 && p[138] != 0.0;
}

FullDayTerms full_day_terms(const FullTable& p, int day_of_year, const SolarActivity& activity) {
  const double day = day_of_year;
  FullDayTerms d;
  d.cd32 = std::cos(kDay * (day - p[31]));
  d.cd18 = std::cos(2.0 * kDay * (day - p[17]));
  d.cd14 = std::cos(kDay * (day - p[13]));
  d.cd39 = std::cos(2.0 * kDay * (day - p[38]));
  // F10.7 (Hedin 1987 eq. A22, the F10.7 terms; NRLMSISE-00 adds the dfa^2 term, Picone et al. 2002).
  const double df = activity.f107 - activity.f107a;
  const double dfa = activity.f107a - 150.0;
  d.flux = p[19] * df * (1.0 + p[59] * dfa) + p[20] * df * df + p[21] * dfa + p[29] * dfa * dfa;
  d.f1 = 1.0 + (p[47] * dfa + p[19] * df + p[20] * df * df);
  d.f2 = 1.0 + (p[49] * dfa + p[19] * df + p[20] * df * df);
  if (history_mode(activity)) {
    for (std::size_t k = 0; k < 6; ++k) d.history_scaled[k] = history_scaled_ap((*activity.ap_history)[k + 1], p);
  }
  if (!magnetic_depends_on_latitude(p, activity)) d.magnetic = magnetic_function(p, activity, 0.0);
  return d;
}

LowerDayTerms lower_day_terms(const LowerTable& p, int day_of_year) {
  const double day = day_of_year;
  LowerDayTerms d;
  d.cd32 = std::cos(kDay * (day - p[31]));
  d.cd18 = std::cos(2.0 * kDay * (day - p[17]));
  d.cd14 = std::cos(kDay * (day - p[13]));
  d.cd39 = std::cos(2.0 * kDay * (day - p[38]));
  d.lon_annual = p[80] * std::cos(kDay * (day - p[81])) + p[85] * std::cos(2.0 * kDay * (day - p[86]));
  d.lon_constant = p[83] * std::cos(kDay * (day - p[84])) + p[87] * std::cos(2.0 * kDay * (day - p[88]));
  return d;
}

FullPhaseTerms direct_phase_terms(const FullTable& p, const Basis& b, bool history) {
  const auto& i = history ? kHistoryPhaseIndex : kDailyPhaseIndex;
  FullPhaseTerms t;
  t.lt_magnetic = std::cos(kHour * (b.lst_h - p[at(i[0])]));
  t.ut = std::cos(kSecond * (b.ut_seconds - p[at(i[1])]));
  t.ut_lon = std::cos(kSecond * (b.ut_seconds - p[at(i[2])]) + 2.0 * kDegree * b.longitude_deg);
  t.lon_magnetic1 = std::cos(kDegree * (b.longitude_deg - p[at(i[3])]));
  t.lon_magnetic2 = std::cos(kDegree * (b.longitude_deg - p[at(i[4])]));
  t.ut_magnetic = std::cos(kSecond * (b.ut_seconds - p[at(i[5])]));
  return t;
}

FullPhaseConstants phase_constants(const FullTable& p, bool history) {
  const auto& i = history ? kHistoryPhaseIndex : kDailyPhaseIndex;
  FullPhaseConstants k;
  for (std::size_t j = 0; j < 6; ++j) {
    k.cos_phase[j] = std::cos(kPhaseScale[j] * p[at(i[j])]);
    k.sin_phase[j] = std::sin(kPhaseScale[j] * p[at(i[j])]);
  }
  return k;
}

FullPhaseTerms cached_phase_terms(const FullPhaseConstants& k, const Basis& b) {
  // cos(a - q) = cos a cos q + sin a sin q.
  const auto& c = k.cos_phase;
  const auto& s = k.sin_phase;
  FullPhaseTerms t;
  t.lt_magnetic = b.cos_lt1 * c[0] + b.sin_lt1 * s[0];
  t.ut = b.cos_ut * c[1] + b.sin_ut * s[1];
  t.ut_lon = b.cos_ut_lon * c[2] + b.sin_ut_lon * s[2];
  t.lon_magnetic1 = b.cos_lon * c[3] + b.sin_lon * s[3];
  t.lon_magnetic2 = b.cos_lon * c[4] + b.sin_lon * s[4];
  t.ut_magnetic = b.cos_ut * c[5] + b.sin_ut * s[5];
  return t;
}

// long-function: one expression per term of Hedin (1987) eq. A22, kept together so that it
// reads against the published list of terms.
double full_expansion(const FullTable& p, const Basis& b, const FullDayTerms& d, const FullPhaseTerms& ph,
                      double magnetic, bool history) {
  const auto& l = b.legendre;
  const double dfa = b.dfa;
  // Time independent, symmetric annual and semiannual, asymmetric annual and semiannual.
  const double t1 = (p[1] * l[0][2] + p[2] * l[0][4] + p[22] * l[0][6]) + (p[14] * l[0][2]) * dfa + p[26] * l[0][1];
  const double t2 = p[18] * d.cd32;
  const double t3 = (p[15] + p[16] * l[0][2]) * d.cd18;
  const double t4 = d.f1 * (p[9] * l[0][1] + p[10] * l[0][3]) * d.cd14;
  const double t5 = p[37] * l[0][1] * d.cd39;
  // Diurnal, semidiurnal tides.
  const double t71 = (p[11] * l[1][2]) * d.cd14;
  const double t72 = (p[12] * l[1][2]) * d.cd14;
  const double t6 = d.f2 * ((p[3] * l[1][1] + p[4] * l[1][3] + p[27] * l[1][5] + t71) * b.cos_lt1 +
                            (p[6] * l[1][1] + p[7] * l[1][3] + p[28] * l[1][5] + t72) * b.sin_lt1);
  const double t81 = (p[23] * l[2][3] + p[35] * l[2][5]) * d.cd14;
  const double t82 = (p[33] * l[2][3] + p[36] * l[2][5]) * d.cd14;
  const double t7 = d.f2 * ((p[5] * l[2][2] + p[41] * l[2][4] + t81) * b.cos_lt2 +
                            (p[8] * l[2][2] + p[42] * l[2][4] + t82) * b.sin_lt2);
  // Terdiurnal tide.
  const double t13 = d.f2 * ((p[39] * l[3][3] + (p[93] * l[3][4] + p[46] * l[3][6]) * d.cd14) * b.sin_lt3 +
                             (p[40] * l[3][3] + (p[94] * l[3][4] + p[48] * l[3][6]) * d.cd14) * b.cos_lt3);
  // Geomagnetic activity, zonal and diurnal.
  double t8 = 0.0;
  if (!history) {
    t8 = magnetic * (p[32] + p[45] * l[0][2] + p[34] * l[0][4] +
                     (p[100] * l[0][1] + p[101] * l[0][3] + p[102] * l[0][5]) * d.cd14 +
                     (p[121] * l[1][1] + p[122] * l[1][3] + p[123] * l[1][5]) * ph.lt_magnetic);
  } else if (p[51] != 0.0) {
    t8 = magnetic * (p[50] + p[96] * l[0][2] + p[54] * l[0][4] +
                     (p[125] * l[0][1] + p[126] * l[0][3] + p[127] * l[0][5]) * d.cd14 +
                     (p[128] * l[1][1] + p[129] * l[1][3] + p[130] * l[1][5]) * ph.lt_magnetic);
  }
  // Longitude.
  const double t10 =
      (1.0 + p[80] * dfa) *
      ((p[64] * l[1][2] + p[65] * l[1][4] + p[66] * l[1][6] + p[103] * l[1][1] + p[104] * l[1][3] +
        p[105] * l[1][5] + (p[109] * l[1][1] + p[110] * l[1][3] + p[111] * l[1][5]) * d.cd14) *
           b.cos_lon +
       (p[90] * l[1][2] + p[91] * l[1][4] + p[92] * l[1][6] + p[106] * l[1][1] + p[107] * l[1][3] +
        p[108] * l[1][5] + (p[112] * l[1][1] + p[113] * l[1][3] + p[114] * l[1][5]) * d.cd14) *
           b.sin_lon);
  // UT and mixed UT-longitude.
  double t11 = (1.0 + p[95] * l[0][1]) * (1.0 + p[81] * dfa) * (1.0 + p[119] * l[0][1] * d.cd14) *
               ((p[68] * l[0][1] + p[69] * l[0][3] + p[70] * l[0][5]) * ph.ut);
  t11 += (p[76] * l[2][3] + p[77] * l[2][5] + p[78] * l[2][7]) * ph.ut_lon * (1.0 + p[137] * dfa);
  // UT-longitude geomagnetic activity.
  double t12 = 0.0;
  if (!history) {
    t12 = magnetic * (1.0 + p[120] * l[0][1]) * ((p[60] * l[1][2] + p[61] * l[1][4] + p[62] * l[1][6]) * ph.lon_magnetic1) +
          magnetic * (p[115] * l[1][1] + p[116] * l[1][3] + p[117] * l[1][5]) * d.cd14 * ph.lon_magnetic2 +
          magnetic * (p[83] * l[0][1] + p[84] * l[0][3] + p[85] * l[0][5]) * ph.ut_magnetic;
  } else if (p[51] != 0.0) {
    t12 = magnetic * (1.0 + p[132] * l[0][1]) * ((p[52] * l[1][2] + p[98] * l[1][4] + p[67] * l[1][6]) * ph.lon_magnetic1) +
          magnetic * (p[133] * l[1][1] + p[134] * l[1][3] + p[135] * l[1][5]) * d.cd14 * ph.lon_magnetic2 +
          magnetic * (p[55] * l[0][1] + p[56] * l[0][3] + p[57] * l[0][5]) * ph.ut_magnetic;
  }
  // The published sum, in its order (term 9 is unused).
  double g = p[30];
  for (const double t : {d.flux, t1, t2, t3, t4, t5, t6, t7, t8, t10, t11, t12, t13}) g += t;
  return g;
}

double lower_expansion(const LowerTable& p, const Basis& b, const LowerDayTerms& d, double magnetic, bool history) {
  const auto& l = b.legendre;
  const double t0 = p[21] * b.dfa;
  const double t1 = p[1] * l[0][2] + p[2] * l[0][4] + p[22] * l[0][6] + p[26] * l[0][1] + p[14] * l[0][3] + p[59] * l[0][5];
  const double t2 = (p[18] + p[47] * l[0][2] + p[29] * l[0][4]) * d.cd32;
  const double t3 = (p[15] + p[16] * l[0][2] + p[30] * l[0][4]) * d.cd18;
  const double t4 = (p[9] * l[0][1] + p[10] * l[0][3] + p[20] * l[0][5]) * d.cd14;
  const double t5 = (p[37] * l[0][1]) * d.cd39;
  const double t71 = p[11] * l[1][2] * d.cd14;
  const double t72 = p[12] * l[1][2] * d.cd14;
  const double t6 = (p[3] * l[1][1] + p[4] * l[1][3] + t71) * b.cos_lt1 + (p[6] * l[1][1] + p[7] * l[1][3] + t72) * b.sin_lt1;
  const double t81 = (p[23] * l[2][3] + p[35] * l[2][5]) * d.cd14;
  const double t82 = (p[33] * l[2][3] + p[36] * l[2][5]) * d.cd14;
  const double t7 = (p[5] * l[2][2] + p[41] * l[2][4] + t81) * b.cos_lt2 + (p[8] * l[2][2] + p[42] * l[2][4] + t82) * b.sin_lt2;
  const double t13 = p[39] * l[3][3] * b.sin_lt3 + p[40] * l[3][3] * b.cos_lt3;
  const double t8 = history ? p[50] * magnetic + p[96] * l[0][2] * magnetic : magnetic * (p[32] + p[45] * l[0][2]);
  const double t10 = (1.0 + l[0][1] * d.lon_annual + d.lon_constant) *
                     ((p[64] * l[1][2] + p[65] * l[1][4] + p[66] * l[1][6] + p[74] * l[1][1] + p[75] * l[1][3] +
                       p[76] * l[1][5]) * b.cos_lon +
                      (p[90] * l[1][2] + p[91] * l[1][4] + p[92] * l[1][6] + p[77] * l[1][1] + p[78] * l[1][3] +
                       p[79] * l[1][5]) * b.sin_lon);
  double g = 0.0;
  for (const double t : {t0, t1, t2, t3, t4, t5, t6, t7, t8, t10, t13}) g += t;
  return g;
}

}  // namespace visors::dynamics::nrlmsise00_detail
