//! # The solved D-form as a design object
//!
//! What a student casting the form needs from [`crate::simulate`]'s mesh, beyond its volume:
//!
//! - [`extents`]: the form's overall height, width and depth along its principal axes (the
//!   eigenvectors of the surface's second moment), for sizing a mould;
//! - [`place`]: a point of a flat piece (a hole centre, a label, a start mark) carried onto the
//!   3D surface through the mesh's per-triangle flat corners (`Simulation::flat`), so connectors
//!   can be drawn where they end up on the form.
//!
//! Both work on the plain mesh arrays (the same fields as the `simulate` result), so the contract
//! layer can hand them a result that went through JSON or JS and back.

pub mod extents;
pub mod place;

pub use extents::{principal_extents, Extents};
pub use place::place;
