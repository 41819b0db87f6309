//! Roundings below the seam's resolution previewed as corners, when the sheet path cannot follow
//! them.
//!
//! A star drawn with sharp corners and then rounded by a fraction of a millimetre (Illustrator's
//! Round Corners) has tips the seam's graded steps must resolve: a 0.25 mm rounding of a 344 mm
//! star takes about fifteen of 256 seam samples, and the sheet around them triangles of a few
//! hundredths of a millimetre. From its convex twins the sheet path crumples there ([`super::kink`]'s
//! docs, stop 55). Star polygons with a circle (five, six and seven points, valleys at 0.45 and
//! 0.6 of the tips' radius, 256 seam vertices, native), every corner rounded by 0.1 or 0.25 mm:
//! 10 of 12 ended stretched by 13–505 %, the other two by 1.6e-3 and 1.8e-3, in 1–6 s, where
//! the same stars with sharp corners end creased or converged in 0.2 s. Nor does a good start
//! help: the sheet solved with the tips taken as corners, carried onto the real meshes by flat
//! position, starts 78–95 % strained on the tips' tiny triangles, and thinned from there ends
//! 36–69 % strained (one of eight at 6.3e-3) from `kb/R²` = 1e-5, 96–100 % from 1e-3.
//!
//! Taken as corners (the seam's kinks at [`Limits::CORNERS`]: every turn tighter than the seam
//! resolves becomes one seam vertex at the rounding's middle), the same stars follow the sharp
//! stars' path, in 0.15–0.5 s. Such an answer is an honest approximation: its flat corners are
//! points of the real outlines, and the strain it reports is what its chords make of the
//! roundings (the walk's deficits spread over the seam, and `d²/2h` beside each kink:
//! [`super::kink::KINK_OFFSET`]), mostly the floor of its seam samples, so it is worded as held
//! by its samples ([`Shortfall::Sampling`]) or creased. At 256 seam vertices 11 of the 12 stars
//! end so (strained by at most 1.07e-2, volumes 0.3–6.7 % from their sharp twins'), 10 of them
//! within 0.3 % of their volume at 128; the twelfth (five points, valleys at 0.6, 0.1 mm) ends
//! 7.9e-2 stretched instead of 0.21.
//!
//! Other drawings with such roundings, with a circle (256 seam vertices, native): the dart (one
//! reflex corner) rounded by 0.1 mm ends 8.9e-3 strained, held by its samples, 1.1 % from its
//! sharp twin's volume, where it ended 415 % stretched; rounded by 0.2 mm, 3.8e-2 from 22 %. An
//! 80 mm L with a 40 or 20 mm notch rounded by 0.2 mm ends 11.7 % and 3.2e-3 stretched, from 55 %
//! and 85 %; a four-pointed star polygon rounded by 0.1 or 0.2 mm 2.2e-3 and 1.8e-3 creased, from
//! 96 % and 75 %. Where the sheet's own answer is stretched by only a little the preview can
//! still replace it, as held by its samples: the five-pointed star rounded by 0.3 mm goes from
//! 3.56e-3 stretched at 75,027 mm³ to 1.2e-2 at 82,437 (its sharp twin 82,618), while at 128 the
//! sheet's creased answer (75,773) is kept, so the two resolutions are 8.8 % apart where they
//! were 1 %.
//!
//! So a pair whose answer misses its promise ([`missed`]) and that has turns the seam's own
//! limits do not take as kinks ([`super::seam::Glue::kinks`]) is solved again this way, and the
//! better answer kept as between two starts ([`super::anchor::better`]). A converged or creased
//! answer, or one held by its own samples, is never replaced; no pair of the survey (309 pairs
//! of organic shapes, copies and mirror images) is solved again. It comes before the second
//! start ([`super::anchor::retry`]), which then runs only if the preview misses too. With the
//! preview after it, the second start took the two five-pointed stars rounded by 0.25 mm to
//! 4.3–4.5 s native and gave neither a better answer; with it before, they take 2.6–2.9 s, and
//! all twelve stars end as they did.
//!
//! [`Limits::CORNERS`]: super::kink::Limits::CORNERS

use super::{Shortfall, Simulation};

/// Whether an answer (judged, [`super::stats::judge`]) is one a corner preview may replace: it
/// misses its promise by stretching, crossing or not settling. A converged answer, a crease
/// that keeps every flat length ([`Shortfall::Fold`]) and an answer as isometric as its samples
/// allow ([`Shortfall::Sampling`]) are kept.
pub fn missed(sim: &Simulation) -> bool {
    matches!(sim.stats.shortfall, Some(Shortfall::Stretch | Shortfall::Crossing | Shortfall::Unsettled))
}
