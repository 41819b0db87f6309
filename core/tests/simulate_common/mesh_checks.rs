//! Independent checks of a returned mesh, computed from `vertices`, `triangles` and `flat` only
//! (never from the solver's stats): isometry against the flat pieces, closure, folds and
//! self-intersection.
#![allow(dead_code)]

use dformer::simulate::Simulation;
use std::collections::HashMap;

pub type V3 = [f64; 3];

pub fn sub(a: V3, b: V3) -> V3 {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}
pub fn dot(a: V3, b: V3) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}
pub fn cross(a: V3, b: V3) -> V3 {
    [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]
}
pub fn norm(a: V3) -> f64 {
    dot(a, a).sqrt()
}

/// Largest |3D length / flat length − 1| over every triangle side, the flat length read from
/// `flat` (each triangle's corners on its own piece).
pub fn max_edge_strain(s: &Simulation) -> f64 {
    let mut worst = 0.0f64;
    for (t, tri) in s.triangles.iter().enumerate() {
        for (a, b) in [(0, 1), (1, 2), (2, 0)] {
            let f = s.flat[t];
            let d = (f[a][0] - f[b][0]).hypot(f[a][1] - f[b][1]);
            let l = norm(sub(s.vertices[tri[a]], s.vertices[tri[b]]));
            worst = worst.max((l / d - 1.0).abs());
        }
    }
    worst
}

/// The seam samples' floor: the largest `(c₂ − c₁)/(c₁ + c₂)` over seam edges whose two flat
/// lengths (one per piece, read from `flat`) are `c₁ < c₂`. No realization of these flat
/// triangles has a smaller [`max_edge_strain`]: one 3D length is strained by at least that
/// against one of the two.
pub fn seam_floor(s: &Simulation) -> f64 {
    let n = s.seam.len();
    let next: HashMap<usize, usize> = (0..n).map(|k| (s.seam[k], s.seam[(k + 1) % n])).collect();
    let mut lengths: HashMap<(usize, usize), [f64; 2]> = HashMap::new();
    for (t, tri) in s.triangles.iter().enumerate() {
        for (a, b) in [(0, 1), (1, 2), (2, 0)] {
            let (i, j) = (tri[a], tri[b]);
            if next.get(&i) != Some(&j) && next.get(&j) != Some(&i) {
                continue;
            }
            let f = s.flat[t];
            lengths.entry((i.min(j), i.max(j))).or_insert([0.0; 2])[s.piece[t] as usize] = (f[a][0] - f[b][0]).hypot(f[a][1] - f[b][1]);
        }
    }
    lengths.values().filter(|c| c[0] > 0.0 && c[1] > 0.0).map(|c| (c[0] - c[1]).abs() / (c[0] + c[1])).fold(0.0, f64::max)
}

/// Whether the mesh is a closed, consistently oriented 2-manifold of genus 0: every directed
/// edge once and its reverse once, every vertex's fan a single cycle, V − E + F = 2.
pub fn closed_manifold(s: &Simulation) -> Result<(), String> {
    let mut directed: HashMap<(usize, usize), usize> = HashMap::new();
    for tri in &s.triangles {
        for (a, b) in [(0, 1), (1, 2), (2, 0)] {
            *directed.entry((tri[a], tri[b])).or_insert(0) += 1;
        }
    }
    for (&(i, j), &c) in &directed {
        if c != 1 {
            return Err(format!("directed edge {i}->{j} used {c} times"));
        }
        if directed.get(&(j, i)) != Some(&1) {
            return Err(format!("edge {i}-{j} is open (no reverse)"));
        }
    }
    // Fans: at vertex v, the map "next" from each triangle's outgoing edge must be one cycle.
    let mut next: HashMap<usize, HashMap<usize, usize>> = HashMap::new();
    for tri in &s.triangles {
        for k in 0..3 {
            let (v, a, b) = (tri[k], tri[(k + 1) % 3], tri[(k + 2) % 3]);
            next.entry(v).or_default().insert(a, b);
        }
    }
    for (v, m) in &next {
        let start = *m.keys().next().unwrap();
        let (mut at, mut len) = (start, 0);
        loop {
            at = m[&at];
            len += 1;
            if at == start || len > m.len() {
                break;
            }
        }
        if len != m.len() {
            return Err(format!("vertex {v}: its fan is not one cycle ({len} of {})", m.len()));
        }
    }
    let (v, e, f) = (next.len() as i64, (directed.len() / 2) as i64, s.triangles.len() as i64);
    if v - e + f != 2 {
        return Err(format!("Euler characteristic {} (V {v}, E {e}, F {f})", v - e + f));
    }
    Ok(())
}

/// Largest bend (angle between the two faces' normals, 0 for flat, π for folded back) across
/// an edge inside one piece (both triangles of the same piece), in radians.
pub fn max_bend_inside(s: &Simulation) -> f64 {
    max_bend_inside_at(s, |_, _| true)
}

/// [`max_bend_inside`] over the edges `(i, j)` that `keep` accepts.
pub fn max_bend_inside_at(s: &Simulation, keep: impl Fn(usize, usize) -> bool) -> f64 {
    bends_inside(s).into_iter().filter(|&((i, j), _)| keep(i, j)).map(|(_, b)| b).fold(0.0, f64::max)
}

/// Every edge `(i, j)` shared by two triangles of the same piece (each once, `i < j`) and the
/// angle between their normals.
pub fn bends_inside(s: &Simulation) -> Vec<((usize, usize), f64)> {
    let mut owner: HashMap<(usize, usize), usize> = HashMap::new();
    let normal = |t: usize| {
        let [a, b, c] = s.triangles[t];
        let n = cross(sub(s.vertices[b], s.vertices[a]), sub(s.vertices[c], s.vertices[a]));
        let l = norm(n);
        n.map(|v| v / l)
    };
    let mut out = Vec::new();
    for (t, tri) in s.triangles.iter().enumerate() {
        for (a, b) in [(0, 1), (1, 2), (2, 0)] {
            let (i, j) = (tri[a], tri[b]);
            if let Some(&u) = owner.get(&(j, i)) {
                if s.piece[u] == s.piece[t] {
                    let (n1, n2) = (normal(u), normal(t));
                    out.push(((i.min(j), i.max(j)), norm(cross(n1, n2)).atan2(dot(n1, n2))));
                }
            } else {
                owner.insert((i, j), t);
            }
        }
    }
    out
}

/// Whether segment p–q crosses triangle (a, b, c) strictly inside both (Möller–Trumbore with
/// a relative margin `eps`); a segment in the triangle's plane does not count.
fn segment_hits(p: V3, q: V3, a: V3, b: V3, c: V3, eps: f64, touch: f64) -> bool {
    let d = sub(q, p);
    let (e1, e2) = (sub(b, a), sub(c, a));
    // Both ends within `touch` of the plane: lying on the triangle (sheets touching), not crossing.
    let n = cross(e1, e2);
    let height = |r: V3| dot(n, sub(r, a)).abs() / norm(n);
    if height(p) <= touch && height(q) <= touch {
        return false;
    }
    let h = cross(d, e2);
    let det = dot(e1, h);
    let scale = norm(e1) * norm(e2) * norm(d);
    if det.abs() <= 1e-9 * scale {
        return false;
    }
    let f = 1.0 / det;
    let s = sub(p, a);
    let u = f * dot(s, h);
    let qv = cross(s, e1);
    let v = f * dot(d, qv);
    let t = f * dot(e2, qv);
    u > eps && v > eps && u + v < 1.0 - eps && t > eps && t < 1.0 - eps
}

/// Pairs of triangles that intersect away from what they share: for triangles with no common
/// vertex, any side of one through the inside of the other; for triangles with one common
/// vertex, the side opposite it. `eps` is a relative margin (barycentric and along the side); a
/// side within 1e-6 of the mesh's size of the other's plane at both ends touches it.
pub fn self_intersections(s: &Simulation, eps: f64) -> Vec<(usize, usize)> {
    let x = &s.vertices;
    let touch = 1e-6 * x.iter().map(|p| norm(*p)).fold(0.0, f64::max);
    let bbox = |t: &[usize; 3]| {
        let mut lo = [f64::INFINITY; 3];
        let mut hi = [f64::NEG_INFINITY; 3];
        for &v in t {
            for a in 0..3 {
                lo[a] = lo[a].min(x[v][a]);
                hi[a] = hi[a].max(x[v][a]);
            }
        }
        (lo, hi)
    };
    let boxes: Vec<_> = s.triangles.iter().map(bbox).collect();
    let mut out = Vec::new();
    for i in 0..s.triangles.len() {
        for j in i + 1..s.triangles.len() {
            let (bi, bj) = (boxes[i], boxes[j]);
            if (0..3).any(|a| bi.1[a] < bj.0[a] || bj.1[a] < bi.0[a]) {
                continue;
            }
            let (ti, tj) = (s.triangles[i], s.triangles[j]);
            let shared: Vec<usize> = ti.iter().copied().filter(|v| tj.contains(v)).collect();
            if shared.len() >= 2 {
                continue;
            }
            let sides = |t: [usize; 3]| -> Vec<(usize, usize)> {
                let all = [(t[0], t[1]), (t[1], t[2]), (t[2], t[0])];
                all.into_iter().filter(|(a, b)| !shared.contains(a) && !shared.contains(b)).collect()
            };
            let hit = sides(ti).iter().any(|&(p, q)| segment_hits(x[p], x[q], x[tj[0]], x[tj[1]], x[tj[2]], eps, touch))
                || sides(tj).iter().any(|&(p, q)| segment_hits(x[p], x[q], x[ti[0]], x[ti[1]], x[ti[2]], eps, touch));
            if hit {
                out.push((i, j));
            }
        }
    }
    out
}

/// Largest height of a vertex above the plane of a face (outward triangles), relative to
/// `size`: zero (to round-off) for a convex mesh, whatever its triangulation. Faces whose
/// doubled area is below 1e-12 of `size`², or whose least height is below `needle` times
/// `size`, are skipped: their planes are round-off (a needle between two samples microns apart
/// and a far vertex is tilted by round-off and by the difference of the pieces' chords).
pub fn outside_faces(s: &Simulation, size: f64, needle: f64) -> f64 {
    let x = &s.vertices;
    let mut worst = 0.0f64;
    for &[i, j, k] in &s.triangles {
        let n = cross(sub(x[j], x[i]), sub(x[k], x[i]));
        let area2 = norm(n);
        let longest = [(i, j), (j, k), (k, i)].iter().map(|&(a, b)| norm(sub(x[a], x[b]))).fold(0.0, f64::max);
        if area2 < 1e-12 * size * size || area2 <= needle * size * longest {
            continue;
        }
        for p in x {
            worst = worst.max(dot(n, sub(*p, x[i])) / area2 / size);
        }
    }
    worst
}

/// Volume of the closed mesh (divergence theorem over its outward triangles).
pub fn volume(s: &Simulation) -> f64 {
    s.triangles.iter().map(|t| dot(s.vertices[t[0]], cross(s.vertices[t[1]], s.vertices[t[2]]))).sum::<f64>() / 6.0
}

/// A one-line account of the checks, for assertion messages and the bench.
pub fn report(s: &Simulation) -> String {
    format!(
        "strain {:.2e}, closed {:?}, max bend inside a piece {:.1}°, self-intersections {}, volume {:.6e}, converged {}",
        max_edge_strain(s),
        closed_manifold(s).err(),
        max_bend_inside(s).to_degrees(),
        self_intersections(s, 1e-9).len(),
        volume(s),
        s.stats.converged
    )
}

/// What a converged answer promises (requirement 1 of issue 14), checked independently.
pub fn promise(s: &Simulation) -> Result<(), String> {
    let strain = max_edge_strain(s);
    if strain > 1e-3 {
        return Err(format!("edge strain {strain:.2e} > 1e-3"));
    }
    closed_manifold(s)?;
    let bend = max_bend_inside(s);
    if bend > std::f64::consts::FRAC_PI_2 {
        return Err(format!("a fold of {:.1}° inside a piece", bend.to_degrees()));
    }
    let crossings = self_intersections(s, 1e-9);
    if !crossings.is_empty() {
        return Err(format!("{} pairs of crossing triangles, first {:?}", crossings.len(), crossings[0]));
    }
    Ok(())
}

/// Each seam vertex and its total angle: its triangles' corners there, both pieces', from `flat`.
pub fn seam_angles(s: &Simulation) -> Vec<(usize, f64)> {
    let mut total = vec![0.0; s.vertices.len()];
    for (t, f) in s.triangles.iter().zip(&s.flat) {
        for k in 0..3 {
            let (o, a, b) = (f[k], f[(k + 1) % 3], f[(k + 2) % 3]);
            let (u, v) = ([a[0] - o[0], a[1] - o[1]], [b[0] - o[0], b[1] - o[1]]);
            total[t[k]] += (u[0] * v[1] - u[1] * v[0]).abs().atan2(u[0] * v[0] + u[1] * v[1]);
        }
    }
    s.seam.iter().map(|&v| (v, total[v])).collect()
}

/// The largest total angle at a seam vertex, both pieces' corners summed from `flat`: above
/// 2π where the glued surface is a saddle.
pub fn largest_seam_angle(s: &Simulation) -> f64 {
    seam_angles(s).into_iter().map(|(_, a)| a).fold(0.0, f64::max)
}

/// Each seam vertex's flat position on piece `piece` (from the triangles of that piece).
pub fn seam_flat(s: &Simulation, piece: u8) -> Vec<[f64; 2]> {
    let mut at = vec![[f64::NAN; 2]; s.vertices.len()];
    for ((t, f), &p) in s.triangles.iter().zip(&s.flat).zip(&s.piece) {
        if p == piece {
            for (&v, &q) in t.iter().zip(f) {
                at[v] = q;
            }
        }
    }
    s.seam.iter().map(|&v| at[v]).collect()
}
