// Displacement RAOs of a vessel: the complex response per unit wave amplitude of its six
// degrees of freedom (surge, sway, heave in m/m; roll, pitch, yaw in rad/m) about a stated
// RAO origin, per wave frequency and heading, stored in seaflex's convention:
//   x_j(t) = Re{ H_j(w, beta) A e^{i w t} },  A = a e^{i (phase - k (o_x cos b + o_y sin b))}
// i.e. the phase of H is a LEAD relative to the wave crest at the RAO origin o (WAMIT
// User Manual v7, sec. 4.4: the .4 file's motions xi = Re{Xi A e^{i w t}} with the
// incident wave of hydro_database.hpp). Readers convert other conventions to this one.
// Interpolation: linear in the real and imaginary parts in w and in the heading, with
// the heading wrap-around and clamping of HydroDatabase::excitation_at (the same layout).
//
// Two readers:
//  - a plain table (CSV or whitespace), one row per (period, heading):
//      period_s, heading_deg, surge_amp, surge_phase, sway_amp, sway_phase, heave_amp,
//      heave_phase, roll_amp, roll_phase, pitch_amp, pitch_phase, yaw_amp, yaw_phase
//    amplitudes in m/m (translations) and deg/m (rotations), phases in deg; every period
//    must be given at every heading (no gaps); '#' lines and one header line are skipped;
//  - WAMIT `.4` (PER BETA I Mod Pha Re Im, nondimensional: rotations times ULEN).
#pragma once

#include <string>

#include "seaflex/hydro/hydro_database.hpp"

namespace seaflex::hydro {

enum class RaoPhase { kLead, kLag };
enum class RaoPhaseReference { kRaoOrigin, kGlobalOrigin };

struct RaoTable {
  /// omega ascending (rad/s), headings ascending (rad), RAOs [heading][omega] in the
  /// convention of the header; held in a HydroDatabase's excitation for its interpolation
  HydroDatabase data;

  /// H(w, beta); *heading_clamped set when beta is outside the covered headings.
  Vec6c at(double omega, double heading, bool* heading_clamped = nullptr) const {
    return data.excitation_at(omega, heading, nullptr, heading_clamped);
  }
};

/// Reads the plain table at path, its phases given in `phase` convention. Throws
/// InputError with file:line and the column's key (period_s, heading_deg, surge_amp, ...)
/// for a missing column, a value that is not a finite number, a negative amplitude or
/// period, a repeated row, or gaps ("table" key: a period missing at some heading).
RaoTable read_rao_table(const std::string& path, RaoPhase phase);

/// Reads a WAMIT .4 file (modes 1..6 of one body; generalized modes skipped), whose
/// rotations are scaled by 1 / ulen (m). Same errors as read_rao_table.
RaoTable read_wamit_rao(const std::string& path, double ulen, RaoPhase phase);

}  // namespace seaflex::hydro
