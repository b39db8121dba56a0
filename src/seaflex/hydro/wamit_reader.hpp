// Reader of WAMIT numeric output files (WAMIT User Manual v7, ch. 4 "Output"):
//   <stem>.1    added mass and damping:  PER  I  J  Abar(I,J)  [Bbar(I,J)]
//   <stem>.3    diffraction excitation:  PER  BETA  I  Mod(Xbar)  Pha(Xbar)  Re(Xbar)  Im(Xbar)
//   <stem>.hst  hydrostatics:            I  J  Cbar(I,J)
// Column 1 is the period PER (s); PER = -1 denotes zero frequency and PER = 0 infinite
// frequency (those .1 rows carry Abar only). BETA is in degrees. The nondimensional
// coefficients are made dimensional with the length scale L = ULEN (manual sec. 4.1-4.3):
//   A_ij = Abar_ij rho L^k,  B_ij = Bbar_ij rho w L^k,  k = 3, 4, 5 for 0, 1, 2 of i, j in 4..6
//   X_i  = Xbar_i rho g L^m,  m = 2 (i = 1..3), 3 (i = 4..6)
//   C_ij = Cbar_ij rho g L^k, k = 2 + number of rotational indices (2 for (3,3), 3 for
//          (3,4), (3,5), 4 for (4,4), (4,5), (5,5)).
// Limitations: only the default PER column (not frequency or wavenumber, IPERIO != 1);
// only modes 1..6 of one body: rows with a mode > 6 (generalized modes, or a second
// body's modes) are skipped silently; .3 rows with PER <= 0 are skipped.
#pragma once

#include <string>

#include "seaflex/hydro/hydro_database.hpp"

namespace seaflex::hydro {

/// Dimensional scales for read_wamit.
struct WamitUnits {
  double rho = 1025.0;  ///< water density (kg/m^3)
  double g = 9.80665;   ///< gravity (m/s^2), as in the WAMIT run (it scales X and C)
  double ulen = 1.0;    ///< WAMIT's length scale ULEN (m)
};

/// Reads `<stem>.1` (required), `<stem>.3` and `<stem>.hst` (each read if the file exists).
/// A first line that does not start with a number is taken as a header and skipped;
/// blank lines are skipped; Fortran 'D' exponents are accepted. Rows may come in any
/// order. The (i, j) pairs (or .3 modes i) present at any finite period must be present
/// at every finite period (and in the PER = 0 / -1 blocks, when given); pairs absent from
/// the whole file are zero. The .3 file must give every heading at every period of the
/// .1 file and no other period; its Re/Im columns are used and must agree with Mod/Pha
/// (1e-4 relative to the modulus). In .hst, absent pairs are zero.
/// Throws seaflex::InputError with one Diagnostic{file, line, 0, key, message} per
/// problem (up to 20 per file), e.g. "sphere.1:12:0: Abar: expected a number, got 'abc'".
/// Keys: "file" (missing <stem>.1, line 0), "PER", "BETA", "mode i", "mode j", "Abar",
/// "Bbar", "Mod(X)", "Pha(X)", "Re(X)", "Im(X)", "Cbar", "modes" (a pair or mode missing
/// at some period), "headings" (a heading missing at some period).
/// Throws std::invalid_argument for rho, g or ulen <= 0.
HydroDatabase read_wamit(const std::string& stem, const WamitUnits& units);

}  // namespace seaflex::hydro
