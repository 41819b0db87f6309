//! The seam level a pair is solved on, the same whatever resolution is asked: the requested
//! resolution's answer is the level's answer refined at the seam.
//!
//! *Why.* A thin sheet glued from a non-convex pair has several stable equilibria, a few
//! percent apart in volume, and the path falls into one of them at its first thick stages
//! ([`super::SCHEDULE`]'s 1e-5 and 1e-6). The kidney with a circle, 128 seam vertices, its
//! drawing started at its 9th knot: from the same homotopy's end, four starts nudged by 1 % of
//! the radius end the 1e-6 stage at bending energies of 105 to 118 (discrete, unit weight) on
//! one mesh, and the thinning takes them to 242,000 or 250,000 mm³; each is a true minimum (a
//! thousand more steps to a relative energy drop of 1e-14 move none by 1 mm³). Which one a
//! solve fell into was decided by its mesh, and the meshes at 128 and 256 seam vertices were
//! two draws: until stop 48 each resolution was meshed and solved on its own. Over eight first
//! anchors (the same outline started at another knot), native, the volumes at 128 and 256 were
//! 1.34 % apart at the median for the kidney (3 of 8 within 1 %), 0.95 % for the five lobes (4 of
//! 8), 0.20 % for the blob, each with a circle. A finer interior mesh does not narrow it
//! (interior edges of 3.5 and 2.5 seam steps instead of 5: the kidney's spread stays 0.4–3.8 %),
//! nor does thinning in smaller steps, a path through other homotopy weights, or thinning the
//! thick stages on a shared level and only the thin ones on each resolution's mesh (kidney
//! median 0.24 %, but the blob 0.4 % and two kidneys creased at 256: the thin stages on the
//! other mesh fall into other minima again). Nor can the thinning be coarsened: thinned on the
//! homotopy's coarser mesh and only relaxed on the fine one at the last stage, every pair ended
//! in another equilibrium, bent more (discrete bending energy 7–30 % higher; Pebble 46.9
//! against 41.2, five lobes 148 against 134).
//!
//! *How.* The level is the requested samples every [`stride`]-th, 128 to 255 of them
//! ([`LEVEL_MIN`]); the samples nest, so 128, 256 and 512 share the level of 128. The level is
//! solved as a request of its own would be (the homotopy on its samples meshed with interior
//! edges [`COARSE_STRIDE`] times longer, [`homotopy`], at every resolution that has a level,
//! its own included; then the thinning and the refinement where the sheet locks), and its
//! answer is carried ([`super::refine::carry`]) onto the level's own triangles with those on the
//! seam split into fans over the requested samples ([`nested`]): the carried shape is the level's
//! equilibrium away from the seam, strained only in the fans. It is relaxed there from the
//! bending weight the level ended at, so it stays in the level's equilibrium and only the seam is
//! resolved finer, and where that bends a smooth pair by just over 90° between two triangles
//! it is refined there as on its own samples ([`super::adapt`]). Over the same eight first
//! anchors, 128 against 256 (native), all converged at both: the kidney 0.03–0.05 %, the five
//! lobes and the blob 0.05–0.06 %, the Pebble 0.00–0.11 %. A request at 256 costs its level's
//! solve and a short relaxation: with a circle, the kidney 279 ms native (its own path 274),
//! the five lobes 200 (340), the blob 192 (321), the Pebble 148 (202), the heart drawn with
//! corners 200 (303).
//!
//! What is left is which equilibrium the level falls into: over the eight first anchors the
//! kidney's volume at 256 seam vertices spanned 244,657–252,485 mm³. Since stop 49 a drawing is
//! solved from its outline's canonical start whatever its first anchor
//! ([`crate::simulate::anchor`]), so it gets one of them; which one is still a draw of its mesh
//! (`bench/simulate.bench.mjs` prints the spread over knots nudged by 0.01 mm). Where the
//! level's answer is not sound, or refined it is graded worse, the requested samples are solved
//! on their own, as before.
//!
//! *A level whose samples cannot be isometric (stop 54).* Where a tight turn makes one piece's
//! chord of a level seam edge and the other's differ by more than the target ([`floor`]), the
//! level cannot converge, and until stop 54 it was skipped: the requested samples were solved on
//! their own, and fell into another equilibrium than 128's: of the 15 stars with a circle below,
//! 8 were more than 1 % from their volume at 128 (up to 2.3 %: a four-tipped star, a
//! seven-pointed star polygon rounded by 3 mm), and a six-tipped star ended stretched (1.1e-3)
//! after 7.8 s, native. Such a level is now the path as any other, its answer need only be as
//! isometric as its samples allow ([`Attempt::sound_on`]), and its refinement:
//!
//! - where the requested samples can converge, stands only if it converges (with no rounds of
//!   [`adapt`]: their own path, which has them, follows when it does not). Of 34 stars (polar ones
//!   with 4–7 tips, and star polygons with 5–7 points rounded by 1–6 mm) 15 now converge so,
//!   within 0.05–0.16 % of 128's volume; the six-tipped star in 0.45 s (WASM: 0.69 s, where it
//!   ended stretched after 11.2 s). Where the refinement does not converge, the level cost
//!   0.1–0.3 s (star polygons, native). A level whose floor does not fall as its samples'
//!   spacing would ([`SPACED`]: the smooth heart's) is not tried. Of the survey's 309 pairs, no
//!   answer changes.
//! - where they cannot either, need only be as isometric as they allow. The rounded star of the
//!   tests (floors 4.2e-3 at 128 and 1.06e-3 at 256) was folded by 106° at 256, 198,124 mm³
//!   against 210,140 at 128 (5.7 % apart; 2.6 % in the WASM bench's star), and is now 210,465
//!   mm³, 1.24e-3 strained, bent by 79° at most (0.15 % from 128), in 0.47 s as before; the WASM
//!   bench's star 0.12 % from 128 (213,288 against 213,026 mm³), bent by 82°.
//!
//! *Where the nested mesh holds the level's answer (stop 52).* The kidney with its mirror image
//! at 6/16, 11/16 and 15/16 of its perimeter converges on the level and ends 7.7e-3 to 9.0e-3
//! strained on the nested mesh, at one new sample each (187, 17 and 183 of 256), inside a stretch
//! where the seam is a saddle ([`super::saddle`]) and near its sharpest point. The strained edges
//! are that sample's two seam edges and its single interior edge in each piece (to the level
//! triangle's apex), then the apex's spokes to the level samples beside it. The refinement frees
//! 11/16 in one round and not the other two, which are then solved on their own samples (after
//! 0.5 and 0.7–0.9 s native of refinement). A vertex on each such sample's spoke, a third or
//! half of the way to the apex, did not free them either. Nor does a mesh of its own (stop 53):
//! the level's converged shape at 6/16 carried onto the requested samples' own Delaunay mesh
//! ([`super::first`]'s) and thinned from the level's stage ends 7.1e-3 strained, 2.1e-3 after
//! the refinement rounds. The lock is the level's equilibrium at the finer samples, not the fan
//! triangles; the own path finds another equilibrium, 0.8 % larger in volume.

use super::glued::SheetMesh;
use super::retry::Attempt;
use super::{adapt, finish, homotopy_on, refine, saddle, thin, Path, HOMOTOPY_KB, INTERIOR_EDGE, SCHEDULE, STRAIN_TARGET};
use crate::simulate::checks::faces_cross;
use crate::simulate::metric::is_seam;
use crate::simulate::progress::Reporter;
use crate::simulate::seam::SeamPieces;
use crate::simulate::vec3::V3;

/// How many times longer the interior edges of the homotopy's mesh are than those of the
/// thinning's ([`super::INTERIOR_EDGE`]): the homotopy is a thick sheet's path (a few percent
/// strain, smooth), which a coarser mesh follows as well. At 256 seam vertices, on a coarse
/// mesh of every second seam sample with edges twice as long (the same mesh in seam steps,
/// about a third of the vertices), the Pebble, blob, kidney and five lobes with a circle ended
/// in the same equilibria (volumes within 0.3 %) in 60–80 % of the time, native and
/// interleaved. And at 512 seam vertices it is what lets a reflex corner through: there the
/// fine twins' interior map inflates the fan at the corner 2.5–4 times (a conformal map is
/// singular at a reflex corner) and the L's and the dart's homotopies crumpled (67–72 % strain,
/// the convex path's 3–15 % strained answer was returned); from the coarse level both end
/// isometric (L 84,341 mm³, 256 seam vertices: 82,049).
pub const COARSE_STRIDE: usize = 2;

/// Where the level's samples cannot be isometric ([`floor`]) and the requested ones can, the
/// level is the path only when its floor is its samples' spacing: when the requested samples'
/// floor is at most the level's over `SPACED` times the stride squared. A chord of a tight
/// turn is short of the other piece's by `(hκ)²/48` of its length, so halving the step `h`
/// quarters the floor: stars with a circle (polar ones with 4–7 tips, star polygons rounded by
/// 1–6 mm) fall by 3.9–4.3 from 128 to 256 samples. The smooth heart with a circle, its copy or
/// its mirror image falls by 1.5–1.75 only, and its level ended through itself or did not
/// converge refined on every one of the survey's 31 such pairs, at 0.3–1.1 s each native (the
/// heart with a circle in WASM: 1.19 s against 0.85).
pub const SPACED: f64 = 0.75;

/// Fewest seam samples of the level ([`stride`]); below it the path runs on the requested
/// mesh alone, as it did before there was a level.
pub const LEVEL_MIN: usize = 128;

/// The stride from `n` seam samples to the level: the largest power of two `s` that divides `n`
/// with `n / s` at least [`LEVEL_MIN`]; `None` below [`LEVEL_MIN`] samples.
pub fn stride(n: usize) -> Option<usize> {
    if n < LEVEL_MIN {
        return None;
    }
    let mut s = 1;
    while n % (2 * s) == 0 && n / (2 * s) >= LEVEL_MIN {
        s *= 2;
    }
    Some(s)
}

/// The homotopy's end on the level: its coarse mesh, the shape on it, and the steps taken.
pub struct Start {
    pub mesh: SheetMesh,
    pub x: Vec<V3>,
    pub steps: usize,
}

/// The homotopy from convex twins followed on the level's samples meshed with interior edges
/// [`COARSE_STRIDE`] times longer. `None` below [`LEVEL_MIN`] seam samples or when the level's
/// twins cannot be solved within [`super::TWIN_BUDGET`]: this mesh is a shortcut, so it gets no
/// rescue (the requested mesh's homotopy, which has one, follows).
pub fn homotopy(pieces: &SeamPieces, path: Path, report: &mut Reporter) -> Option<Start> {
    let level = pieces.every(stride(pieces.n)?);
    let mesh = SheetMesh::new(&level, INTERIOR_EDGE * COARSE_STRIDE as f64)?;
    let (_, x, steps) = homotopy_on(&level, &mesh, false, path, report)?;
    Some(Start { mesh, x, steps })
}

/// The requested mesh of `pieces` nested on the level's mesh `level`: the level's triangles,
/// each one on a level seam edge split into a fan over the requested samples along that edge
/// (the level's samples are every `stride`-th of them), and nothing else changed. The two meshes
/// share every other triangle, vertex for vertex, so the level's shape carried onto it is the
/// level's equilibrium away from the seam, and no triangulation is redone: a Delaunay mesh of
/// the same points redrawn decided its near-cocircular ties on the samples' last bits (the five
/// lobes with an ellipse a period on got other triangles). `None` when a level triangle has two
/// seam edges, or a fan triangle is not a proper one (its flat area under 1e-9 of the
/// original's or of the other orientation).
pub fn nested(pieces: &SeamPieces, level: &SheetMesh) -> Option<SheetMesh> {
    let (n, m) = (pieces.n, level.n);
    if m == 0 || n % m != 0 {
        return None;
    }
    let s = n / m;
    let id = |v: usize| if v < m { v * s } else { v - m + n };
    let total = level.vertex_count() - m + n;
    let mut flat = [vec![[f64::NAN; 2]; total], vec![[f64::NAN; 2]; total]];
    let mut faces: [Vec<[usize; 3]>; 2] = [Vec::new(), Vec::new()];
    for p in 0..2 {
        flat[p][..n].copy_from_slice(&pieces.flat[p].pts);
        for v in m..level.vertex_count() {
            flat[p][id(v)] = level.flat[p][v];
        }
        let area = |t: [usize; 3]| {
            let [a, b, c] = t.map(|v| flat[p][v]);
            (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])
        };
        for t in &level.faces[p] {
            let edges: Vec<usize> = (0..3).filter(|&k| t[k] < m && t[(k + 1) % 3] < m && is_seam(m, t[k], t[(k + 1) % 3])).collect();
            let mapped = t.map(id);
            match edges[..] {
                [] => faces[p].push(mapped),
                [k] => {
                    let (u, w, c) = (mapped[k], mapped[(k + 1) % 3], mapped[(k + 2) % 3]);
                    let up = (u + s) % n == w;
                    let whole = area(mapped);
                    for i in 0..s {
                        let (a, b) = if up { ((u + i) % n, (u + i + 1) % n) } else { ((u + n - i) % n, (u + 2 * n - i - 1) % n) };
                        let fan = [a, b, c];
                        if !(area(fan) / whole > 1e-9) {
                            return None;
                        }
                        faces[p].push(fan);
                    }
                }
                _ => return None,
            }
        }
    }
    Some(SheetMesh { n, faces, flat })
}

/// The sheet path's first answer on the level (every `stride`-th seam sample,
/// [`super::first`]), carried onto the requested mesh nested on it ([`nested`]) and relaxed
/// there from the bending weight it ended at. `None` (the requested samples are then solved on
/// their own, [`super::own`]) when the level's answer is not as sound as its samples allow
/// ([`Attempt::sound_on`]), or the refined one is graded worse ([`Attempt::grade`]: a converged
/// answer that no longer converges, a crease that stretches). Refined from a level whose
/// samples cannot converge ([`floor`]), it must converge where the requested samples can, and
/// be as sound as they allow where they cannot. A far-off level is not
/// followed again on other paths ([`super::retry`]): those run on the requested samples, where
/// they found answers the level's did not (the kidney with its copy at 13/16 converged at 256
/// seam vertices and ended 3.4 % strained at 128, stop 48), and with the level's taken first
/// that pair took 2.9 s native at 256 instead of 1.6. The level's homotopy is computed once for
/// both ([`super::FirstStart`]).
///
/// A converged level is told to `report` as the interim form ([`Reporter::interim`]), with
/// `iterations` taken before the sheet path.
pub fn solve(pieces: &SeamPieces, stride: usize, iterations: usize, budget: usize, start: &mut super::FirstStart, report: &mut Reporter) -> Option<Attempt> {
    let level = pieces.every(stride);
    let (coarse, fine) = (floor(&level), floor(pieces));
    let sampled = coarse > STRAIN_TARGET;
    if sampled && fine <= STRAIN_TARGET && fine * SPACED * (stride * stride) as f64 > coarse {
        return None;
    }
    let (_, _, a) = super::first(&level, start, budget, report).ok()?;
    if !a.sound_on(coarse) {
        return None;
    }
    if a.relaxed.converged {
        report.interim(|| finish::simulation(&level, &a.mesh, &a.shell, &a.relaxed.x, iterations + a.relaxed.steps, true));
    }
    let mesh = nested(pieces, &a.mesh)?;
    let x = refine::carry(&a.mesh, &a.relaxed.x, &mesh)?;
    let mut shell = mesh.shell();
    let faces: Vec<[usize; 3]> = mesh.faces.iter().flatten().copied().collect();
    let radius = pieces.flat[0].perimeter / std::f64::consts::TAU;
    let stages: Vec<f64> = SCHEDULE.iter().copied().filter(|&b| b <= a.relaxed.stage).collect();
    let mut quiet = |_| {};
    let mut relaxed = thin(&mut shell, x, radius, budget.saturating_sub(a.relaxed.steps), &stages, &faces, &mut Reporter::new(&mut quiet, stages.len(), false));
    relaxed.steps += a.relaxed.steps;
    // A smooth pair bent by just over 90° between two triangles is refined there, as on its own
    // samples ([`adapt`]): the kidney with its mirror image at half its perimeter, folded by
    // 93.5° on the level's samples and on these, converges so at 256. Not after a sampled
    // level: one that does not converge at once has the requested samples' own path, which
    // refines, next (and where those cannot converge either, nothing is refined).
    let (mesh, shell, relaxed) = if sampled {
        (mesh, shell, relaxed)
    } else {
        adapt::unlock(pieces, &saddle::samples(pieces), Path::plain(HOMOTOPY_KB), (mesh, shell, relaxed), budget, &mut Reporter::new(&mut quiet, adapt::ROUNDS, false))
    };
    let crossing = !relaxed.converged && faces_cross(&relaxed.x, &mesh.faces.iter().flatten().copied().collect::<Vec<_>>());
    let b = Attempt { mesh, shell, relaxed, crossing };
    let kept = match (sampled, fine <= STRAIN_TARGET) {
        (false, _) => b.grade().0 <= a.grade().0,
        // Only a converged refinement stands in for samples that can converge on their own.
        (true, true) => b.relaxed.converged,
        (true, false) => b.sound_on(fine),
    };
    kept.then_some(b)
}

/// The seam samples' floor of the strain ([`super::shell::Shell::strain_floor`]): each seam
/// edge has a flat length on each piece, `L₁ ≤ L₂`, and no shape strains it by less than
/// `(L₂ − L₁)/(L₁ + L₂)` against one of them. Where the level's samples are above
/// [`STRAIN_TARGET`] (the smooth heart with a circle, whose tip's curvature keeps 128 samples
/// above it; the stars of the module docs), its answer cannot converge, and [`solve`] asks
/// less of it.
pub fn floor(pieces: &SeamPieces) -> f64 {
    let n = pieces.n;
    (0..n).map(|k| {
        let (a, b) = (pieces.chord(0, k, (k + 1) % n), pieces.chord(1, k, (k + 1) % n));
        (a - b).abs() / (a + b)
    }).fold(0.0, f64::max)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_level_has_128_to_255_samples_and_nests() {
        for (n, want) in [(64, None), (127, None), (128, Some(1)), (200, Some(1)), (256, Some(2)), (384, Some(2)), (512, Some(4)), (1024, Some(8)), (320, Some(2)), (258, Some(2))] {
            assert_eq!(stride(n), want, "n = {n}");
        }
        for n in [128, 256, 512, 1024] {
            assert_eq!(n / stride(n).unwrap(), 128, "n = {n}");
        }
    }
}
