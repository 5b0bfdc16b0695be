// A volume its scheme accepted and then failed on is meshed again at half
// its size (issue 16 item 4: small features adapt the size rather than
// fail). In the plan => mesh campaign such failures are mostly features
// closer than an element: half the size meshed 47 of 106, a quarter 59
// (bench/RESULTS.md, session 22). A straight sweep that fails at every
// size is then swept the other way at the size asked for (the caps it
// ended on become those it starts from, and the subcaps are imprinted in
// the other order): 15 of the campaign's 103 failures at their own size
// mesh so, 5 of them failing at every finer size (session 25). Every retry
// that meshes is a warning naming the volume, what changed and why the
// first attempt failed.
#pragma once

#include "framework/io/job.h"
#include "framework/pipeline/mesher.h"

#include <map>
#include <optional>
#include <string>
#include <vector>

namespace cooperage::pipeline {

/// What one volume went through.
struct FinerRetry {
  double asked = 0;          ///< the size the settings gave it
  double size = 0;           ///< the size of its latest attempt
  std::string first_reason;  ///< why the attempt at `asked` failed
  /// The straight sweep its first plan made (no journal hint), and whether
  /// the latest attempt swept it the other way (at `asked`).
  std::optional<geom::Vec3> planned_sweep;
  bool turned = false;
  /// It meshed at `asked` but worse than a failing quality check allows
  /// (`first_reason` says how much); see halve_poor_volumes. With
  /// `turned`: swept the other way for its quality (turn_poor_sweeps).
  bool for_quality = false;
  /// turn_poor_sweeps: the worst scaled Jacobian the planned way reached.
  std::optional<double> planned_worst = std::nullopt;
};

/// A straight sweep whose worst element is below this at the size asked
/// for is swept the other way there too, and the better mesh is kept: of
/// the plan => mesh campaign's 374 parts meshed below it at their own size,
/// 168 reach a better worst element the other way, 71 of them 0.2 or more
/// (bench/RESULTS.md, session 43)...
inline constexpr double kTurnPoorSweepsBelow = 0.2;
/// ... and kept only when its worst element is better by this much: a
/// thousandth is no reason to sweep against the plan (31 of the 198
/// campaign parts turned without it gained less).
inline constexpr double kTurnPoorSweepsGain = 0.01;

/// Halves, in `settings`, the size of every volume of `verdicts` a smaller
/// size may mesh (Verdict::finer_may_help) whose size the settings give
/// (its own, else the global one), and records it in `retries` (volume id
/// -> retry). Returns the volumes halved (none: nothing to retry). With
/// `only`, just the volumes it holds.
std::vector<int> halve_failed_volumes(const std::vector<Verdict>& verdicts,
                                      io::MeshSettings& settings,
                                      std::map<int, FinerRetry>& retries,
                                      const std::vector<int>* only = nullptr);

/// Records, for the volumes of `retries`, the straight sweep `plan` (the
/// first attempt's) made where the journal gave no sweep hint.
void note_planned_sweeps(const SchemePlan& plan, const io::MeshSettings& settings,
                         std::map<int, FinerRetry>& retries);

/// Sets, in `settings`, every volume of `verdicts` still refused after the
/// finer retries and swept straight by its first plan back to the size
/// asked for, with a direction hint the other way (then halved again as
/// before, that way). Returns those volumes.
std::vector<int> turn_failed_sweeps(const std::vector<Verdict>& verdicts,
                                    io::MeshSettings& settings, std::map<int, FinerRetry>& retries);

/// The floor a run's checks set on the scaled Jacobian: the largest `min`
/// of its <quality metric="scaled_jacobian" action="fail"> checks; none
/// without such a check.
std::optional<double> failing_scaled_jacobian_floor(const std::vector<io::QualityCheck>& checks);

/// The worst scaled Jacobian of volume `volume`'s elements in `result`'s
/// quality report; none when it has no block there.
std::optional<double> worst_scaled_jacobian(const MeshResult& result, int volume);

/// Halves, in `settings`, the size of every volume of `result` that
/// meshed with a worst scaled Jacobian below `floor` and whose size the
/// settings give; records it in `retries` (for_quality). The user's
/// failing check would reject that mesh (and write nothing), so finer ones
/// are tried first, as for a volume that failed (mesh_model keeps the best
/// attempt). Returns the volumes halved.
std::vector<int> halve_poor_volumes(const MeshResult& result, double floor,
                                    io::MeshSettings& settings, std::map<int, FinerRetry>& retries);

/// Sets, in `settings`, a direction hint the other way on every volume of
/// `result` that meshed with a worst scaled Jacobian below `below`, has a
/// size, and was swept straight by `result.plan` without a journal sweep
/// hint; records it in `retries` (turned, for_quality, planned_worst).
/// Returns those volumes.
std::vector<int> turn_poor_sweeps(const MeshResult& result, double below,
                                  io::MeshSettings& settings, std::map<int, FinerRetry>& retries);

/// Halves, in `settings`, the size of `volumes` once more (their retry in
/// `retries` says the latest size); returns them.
std::vector<int> halve_volumes_again(const std::vector<int>& volumes, io::MeshSettings& settings,
                                     std::map<int, FinerRetry>& retries);

/// A warning for every retried volume that meshed; for one that still
/// failed, its hint says which sizes (and which direction) were tried.
void report_finer_retries(const std::map<int, FinerRetry>& retries, MeshResult& result);

}  // namespace cooperage::pipeline
