// The wet part of a straight or curved member whose points are parametrized by s in
// [0, 1]: given above(s), the height of point s above the instantaneous surface, the
// interval [s0, s1] where above(s) <= 0. The member is taken to cross the surface at most
// once (both ends wet: all wet; both dry: all dry); the crossing is found by the Illinois
// variant of false position (Dowell & Jarratt 1971) to the tolerance in s.
#pragma once

#include <utility>

namespace seaflex::hydro {

/// [s0, s1] with s1 <= s0 when the member is dry.
template <class Above>
std::pair<double, double> wet_interval(const Above& above, double tolerance = 1e-12) {
  const double f0 = above(0.0), f1 = above(1.0);
  if (f0 <= 0.0 && f1 <= 0.0) return {0.0, 1.0};
  if (f0 > 0.0 && f1 > 0.0) return {1.0, 0.0};
  double lo = 0.0, hi = 1.0, flo = f0, fhi = f1, s = 0.5;
  int side = 0;
  for (int it = 0; it < 60 && hi - lo > tolerance; ++it) {
    s = (lo * fhi - hi * flo) / (fhi - flo);
    const double fs = above(s);
    if ((fs <= 0.0) == (flo <= 0.0)) {
      lo = s;
      flo = fs;
      if (side == -1) fhi *= 0.5;
      side = -1;
    } else {
      hi = s;
      fhi = fs;
      if (side == 1) flo *= 0.5;
      side = 1;
    }
  }
  return f0 <= 0.0 ? std::pair{0.0, s} : std::pair{s, 1.0};
}

}  // namespace seaflex::hydro
