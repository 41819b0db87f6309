//! A homotopy of the flat pieces from convex twins to the pieces themselves, along which the
//! sheet is relaxed step by step.
//!
//! Each piece's convex twin is a convex polygon with the same seam edge lengths
//! ([`super::morph`]: the piece's turning angles made convex and re-closed), so the twins glue
//! exactly as the pieces do. Their D-form is a convex polyhedron the convex path finds exactly,
//! so the homotopy starts from an exact shape. Each piece's mesh is carried onto its twin by
//! Tutte's embedding ([`super::tutte`]), and every edge's rest length is then blended from its
//! length on the twin to its length on the piece ([`super::shell::Shell::set_rest_blend`]; a
//! blend of the two flat layouts instead can fold over in between, where they differ much: the
//! kidney with a 2:1 ellipse jumped to 57 % strain a quarter of the way). The seam edges keep
//! their lengths throughout. The sheet follows its equilibrium with a few percent of strain:
//! started from a far-off shape instead (the convex path's approximation of a non-convex pair,
//! strained by up to 70 %), the thick sheet's equilibrium is strained by up to 50 %, and
//! thinning it compresses the pieces into wrinkles.

use super::flatmesh::polygon_area;
use super::morph::Morph;
use super::tutte::embed;
use super::glued::SheetMesh;
use crate::simulate::seam::{FlatPiece, SeamPieces};

/// The meshes' positions on the two pieces' convex twins.
#[derive(Debug, Clone)]
pub struct Homotopy {
    /// Every vertex of piece p on its twin (seam on the twin polygon, interior by Tutte).
    twin: [Vec<[f64; 2]>; 2],
}

impl Homotopy {
    /// `None` when a piece's polygon has no convex twin that closes ([`Morph::new`]).
    pub fn new(pieces: &SeamPieces, mesh: &SheetMesh, circle_share: f64) -> Option<Self> {
        let morph = [0, 1].map(|p| Morph::with_circle_share(&pieces.flat[p].pts, circle_share));
        let [Some(a), Some(b)] = morph else { return None };
        let morph = [a, b];

        let total = mesh.vertex_count();
        let mut twin = [Vec::new(), Vec::new()];
        for p in 0..2 {
            let boundary = morph[p].at(0.0)?;
            twin[p] = embed(&mesh.faces[p], mesh.n, &boundary, total, 1e-12);
        }
        Some(Homotopy { twin })
    }

    /// The twins as sample polygons (the convex path's input).
    pub fn twin_pieces(&self, pieces: &SeamPieces) -> SeamPieces {
        let n = pieces.n;
        let flat = [0, 1].map(|p| {
            let pts: Vec<[f64; 2]> = self.twin[p][..n].to_vec();
            let arc_mid = (0..n).map(|k| {
                let (a, b) = (pts[k], pts[(k + 1) % n]);
                [(a[0] + b[0]) / 2.0, (a[1] + b[1]) / 2.0]
            }).collect();
            let area = polygon_area(&pts);
            FlatPiece { pts, arc_mid, area, perimeter: pieces.flat[p].perimeter }
        });
        SeamPieces { n, flat }
    }

    /// The twins' flat positions of every vertex (t = 0).
    pub fn twin_flat(&self) -> [Vec<[f64; 2]>; 2] {
        self.twin.clone()
    }
}
