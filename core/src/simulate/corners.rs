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
//! end so (strained by at most 1.07e-2, volumes 0.3–6.7 % from their sharp twins'), and all
//! twelve within 0.6 % of their volume at 128 ([`better`]); the twelfth (five points, valleys at
//! 0.6, 0.1 mm) ends 7.9e-2 stretched instead of 0.21.
//!
//! Other drawings with such roundings, with a circle (256 seam vertices, native): the dart (one
//! reflex corner) rounded by 0.1 mm ends 8.9e-3 strained, held by its samples, 1.1 % from its
//! sharp twin's volume, where it ended 415 % stretched; rounded by 0.2 mm, 3.8e-2 from 22 %. An
//! 80 mm L with a 40 or 20 mm notch rounded by 0.2 mm ends 11.7 % and 3.2e-3 stretched, from 55 %
//! and 85 %; a four-pointed star polygon rounded by 0.1 or 0.2 mm 2.2e-3 and 1.8e-3 creased, from
//! 96 % and 75 %.
//!
//! So a pair whose answer is not converged and that has turns the seam's own limits do not take
//! as kinks ([`super::seam::Glue::kinks`]) is solved again this way, and the better answer kept
//! ([`better`]). No pair of the survey (309 pairs of organic shapes, copies and mirror images)
//! has such turns. The preview comes before the second start ([`super::anchor::retry`]), which
//! then runs only if the answer still misses its promise. With the preview after it, the second
//! start took the two five-pointed stars rounded by 0.25 mm to 4.3–4.5 s native and gave neither
//! a better answer; with it before, they take 2.6–2.9 s, and all twelve stars end as they did.
//!
//! [`Limits::CORNERS`]: super::kink::Limits::CORNERS

use super::Simulation;

/// The answer kept of the sheet's `sim` and the corner `preview` (both judged): the better by the
/// grades two starts are compared by ([`super::anchor::better`]: converged; creased or held by
/// its samples; stretched; through itself; within the last two the lesser strain), and the
/// preview when they tie. On tiny roundings the sheet's creased answers are a draw of its
/// meshes and the preview's are not: first taken only where the sheet's answer missed its
/// promise, the five-pointed star rounded by 0.3 mm kept the sheet's crease at 128 seam vertices
/// (75,773 mm³) and took the preview at 256 (82,437; its sharp twin 82,618), 8.1 % apart; the
/// four-pointed one 4.6 %, the five-pointed one with valleys at 0.6 rounded by 0.25 mm 19 %, a
/// dart rounded by 0.2 mm 5.7 %. Preferred on ties, each is the preview at both, within 0.3 %,
/// and every star rounded by 0.1 or 0.25 mm of the sweep above within 0.6 %.
pub fn better(sim: Simulation, preview: Simulation) -> Simulation {
    super::anchor::better(preview, sim)
}
