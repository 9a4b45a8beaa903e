#pragma once
// The leak test of a finished anastomosis (issue 19, item 5): pressurise the lumen of a
// severed vessel whose ends the stitches hold together, and find the largest gap along the
// suture line: leak or no leak, and where.
//
// What opens a suture line. Blood at pressure p in the lumen pushes the two ends apart along
// the axis with the end-cap force p·π·r_i² (r_i the lumen's radius), which only the stitches
// carry across the line; between stitches the cut edges, pushed apart and held only at the
// stitches, bow open. The pressure on the inner wall swells the tube (hoop tension). Both are
// modelled; the inner wall alone would draw the lips straight and narrow the gaps as the
// pressure rises (the reverted first attempt, 057c793). With both, a closed ring of 8
// stitches still narrows a little from 0 to 50 mmHg (0.054 → 0.034 mm) before the thrust
// opens it (0.040 mm at 200 mmHg); a ring with a stitch left out opens from 50 mmHg on.
//
// A conservative minimisation. Every load is a dead load, fixed in the rest configuration, so
// the equilibrium is the minimum of one potential and Newton with a line search on it settles
// on one answer whatever its tolerance (the first attempt re-read a follower pressure and the
// ties' directions in rounds, which crept and never settled: its verdict hung on rounding):
//   Π(x) = Σ_links E_l(x) + Σ_ties E_t(x) − Σ_i F_i·x_i
// over the free nodes (the clamped rings of each end are held), with
//   links   the tissue's own springs and laws (spring_kernels.h);
//   ties    one per pair of pierce points joined by a stitch's thread (LeakTie): with
//           d = p_b − p_a between its points (barycentric on their faces),
//             E_t = ½ k (|d| − L)₊²
//           L the thread between them and k = EA / max(L, t) the thread's axial stiffness
//           (10-0 nylon, EA ≈ 1.1 N: suture_coupling.h; t the wall thickness bounds a short
//           tie's stiffness). A slack tie holds nothing; E_t is convex and C¹;
//   F_i     the pressure on the inner wall: each inner face (a, b, c) at rest, wound so its
//           normal points into the lumen, carries −p·½(b − a) × (c − a), a third per corner,
//           and each corner's third goes half to its inner node and half to that node's outer
//           twin (the same ring and sector): the lumped wall carries its hoop tension in its
//           two hulls, half the wall's thickness each (mesh/vessel.h). Put on the inner hull
//           alone, the load crosses the wall in the radial spokes, compressed; a compressed
//           link is soft across itself (spring_kernels.h: T/l < 0), and at 100 mmHg the inner
//           hull twisted against the outer one, an instability of the lumped network that a
//           wall does not have (the closed ring of 8 did not settle in 50 iterations: a saddle,
//           then further down). Shared, it settles in 6;
//           the end-cap thrust: p·π·r_i² on each end's cut face, spread on the face's corners
//           by their share of its rest area, along the end's axis away from the other end;
//           and the nodes' weight m_i·g.
// Newton's direction solves H δ = −∇Π with the sparse Cholesky factorisation that the newton
// solver uses (solve/supernodal_cholesky.h), on the true Hessian; where compressed links make it
// indefinite (an end buckling under the thrust where no stitch holds it) it is shifted by
// μ·I, μ from 1e-5 of the stiffest link's stiffness up fourfold until it factorises. A
// backtracking (Armijo) line search on Π takes the step (after a shifted direction, which is
// short along the way out of an unstable shape, it also tries doubling it while Π falls as
// Armijo asks). It stops once
//   max_i |∇Π_i| ≤ tolerance · F,   F = max(max_i |F_i|, k_max · ℓ̄)
// (k_max the stiffest link, ℓ̄ the mean rest length: the force scale without load), or after
// `maxIterations` (NotConverged: no verdict). From an equilibrium at p = 0 nothing moves.
//
// The suture line. Around the circumference every `sampleDeg`, about end 0's axis, the lips of
// the two ends at that angle (collide/end_gap.h, cutRingLip), on the outer and on the inner
// hull; the gap there is the axial opening between them, (lip₁ − lip₀)·a with a end 0's unit
// axis, the smaller of the two hulls' and at least 0: blood gets out only where the cut faces
// are apart over the whole wall, and lips drawn past each other (no contact here) are closed.
// At rest it is the scene's gap all round. Angles follow scoring/attempt.h: about end 0's
// axis (clamp → cut), 0° toward the microscope (the camera eye projected on the
// cross-section), right-handed, [0, 360).
//
// Leak: the largest gap above `leakGapWalls` wall thicknesses (LeakTestParams says why half).
//
// Units: mm, g, s; force µN (g·mm/s²), stiffness g/s², pressure mmHg converted at
// 1 mmHg = 133.322 Pa = 133.322 g/(mm·s²) (so p × an area in mm² is a force in µN); angles
// degrees.

#include "microsim/sim/mesh/spring_model.h"
#include "microsim/sim/scene/scene_def.h"

#include <cstdint>
#include <limits>
#include <optional>
#include <vector>

namespace microsim::sim {

class Scene;

/// A point on a tissue face: (u, v, w) on its corners, sum 1.
struct TissuePoint {
  int face = -1;
  Vec3 barycentric = Vec3::Constant(1.0 / 3.0);
};

/// The thread of one stitch between a point of one end and a point of the other.
struct LeakTie {
  TissuePoint a;
  TissuePoint b;
  double length = 0.0;  ///< mm: the most the thread lets a and b part (0: tied point to point)
};

struct LeakTestParams {
  /// mmHg, uniform in the lumen. 100 mmHg: the upper end of normal mean arterial pressure
  /// (70–100 mmHg; Guyton & Hall, Textbook of Medical Physiology, 13th ed., ch. 15), what a
  /// freshly opened arterial anastomosis meets when the clamps come off.
  double pressureMmHg = 100.0;
  /// A gap wider than this many wall thicknesses leaks. Half the wall (50 µm in a 0.1 mm
  /// wall): narrower gaps are the size of a 10-0 needle's holes (70–100 µm across, 50 µm
  /// deep in the line), which the platelet plug seals within minutes of opening the clamps;
  /// at half the wall the cut faces are apart over more than their depth could seal, and the
  /// line bleeds on.
  double leakGapWalls = 0.5;
  double sampleDeg = 2.0;  ///< degrees between samples of the suture line, > 0
  /// µN: the thread's axial rigidity EA (10-0 nylon: E ≈ 3 GPa, d ≈ 22 µm, EA ≈ 1.1 N)
  double threadRigidity = 1.1e6;
  /// relative residual that ends the minimisation (see above)
  double tolerance = 1e-8;
  int maxIterations = 100;  ///< Newton iterations
  /// unit, normal to end 0's axis: 0° of the angles; none = toward the scene's camera eye
  std::optional<Vec3> angleZero;
};

enum class LeakTestStatus : std::uint8_t {
  Solved,           ///< converged: the verdict and the numbers hold
  NoSeveredVessel,  ///< the scene has no end 0 and end 1 of a severed vessel
  NoStitches,       ///< no tie joins the two ends: nothing holds the line
  BadTie,           ///< a tie names a face the tissue does not have
  NotConverged,     ///< the iteration limit came first: no verdict
  SolverFailed,     ///< no descent direction, or a non-finite state: no verdict
};

/// One sample of the suture line.
struct SutureLineSample {
  double angleDeg = 0.0;  ///< [0, 360)
  double gapMm = 0.0;     ///< the axial opening, the narrower hull's, ≥ 0
};

struct LeakResult {
  LeakTestStatus status = LeakTestStatus::Solved;
  bool leak = false;  ///< largestGapMm > thresholdMm (false without a verdict)
  double largestGapMm = std::numeric_limits<double>::quiet_NaN();  ///< pressurised, mm
  double angleDeg = std::numeric_limits<double>::quiet_NaN();      ///< where, [0, 360)
  double thresholdMm = std::numeric_limits<double>::quiet_NaN();   ///< leakGapWalls × wall
  double pressureMmHg = 0.0;                                       ///< as tested
  int iterations = 0;                                              ///< Newton iterations taken
  double residual = 0.0;                                           ///< relative residual at the end
  std::vector<SutureLineSample> line;  ///< every sample, pressurised (empty without a verdict)
  Points x{3, 0};                      ///< the pressurised tissue, 3 by #N (mm)
};

/// The gap along the suture line between end 0 and end 1 of the severed vessel among
/// `def.vessels` at tissue positions x (3 by #N, mm), every params.sampleDeg; empty without
/// both ends.
std::vector<SutureLineSample> sutureLine(const SceneDef& def, const Points& x,
                                         const LeakTestParams& params = {});

/// Pressurises the lumen of the severed vessel of `def` from tissue positions x (3 by #N, mm:
/// the finished anastomosis) held by `ties`, and walks the suture line.
LeakResult leakTest(const SceneDef& def, const Points& x, const std::vector<LeakTie>& ties,
                    const LeakTestParams& params = {});

/// The ties of the scene's suture: every two pierces next to each other along the thread
/// (SutureState::pierces, in chain order) on different ends of the severed vessel, joined by
/// unbroken thread; the length is the thread's between them now. Empty without a suture.
std::vector<LeakTie> sutureTies(const Scene& scene);

/// leakTest on the scene as it is, held by sutureTies.
LeakResult leakTest(const Scene& scene, const LeakTestParams& params = {});

}  // namespace microsim::sim
