//! The solved form as a mesh file, in millimetres (as the panel exports it): STL has no unit and
//! slicers read mm; OBJ has none either and CAD/CAM tools assume mm (the header says so).

use crate::render::face_normal;
use dformer::api::simulate::SimulateDto;

/// ASCII STL, vertices scaled by `mm` (millimetres per unit of the form).
pub fn stl(form: &SimulateDto, mm: f64) -> String {
    let mut out = String::from("solid d-form\n");
    for t in &form.triangles {
        let [a, b, c] = t.map(|i| form.vertices[i].map(|x| x * mm));
        let n = face_normal(&form.vertices, *t); // a uniform scale keeps the direction
        out.push_str(&format!(" facet normal {:e} {:e} {:e}\n  outer loop\n", n[0], n[1], n[2]));
        for p in [a, b, c] {
            out.push_str(&format!("   vertex {:e} {:e} {:e}\n", p[0], p[1], p[2]));
        }
        out.push_str("  endloop\n endfacet\n");
    }
    out.push_str("endsolid d-form\n");
    out
}

/// Wavefront OBJ in mm, one group per piece.
pub fn obj(form: &SimulateDto, mm: f64) -> String {
    let mut out = String::from("# D-former D-form mesh, units: mm\no d-form\n");
    for v in &form.vertices {
        out.push_str(&format!("v {:.6} {:.6} {:.6}\n", v[0] * mm, v[1] * mm, v[2] * mm));
    }
    for (p, name) in [(0u8, "piece_A"), (1, "piece_B")] {
        out.push_str(&format!("g {name}\n"));
        for (t, tri) in form.triangles.iter().enumerate() {
            if form.piece.get(t) == Some(&p) {
                out.push_str(&format!("f {} {} {}\n", tri[0] + 1, tri[1] + 1, tri[2] + 1));
            }
        }
    }
    out
}
