//! # D-former geometry core
//!
//! Pure geometry for D-forms: two flat pieces with equal perimeters, stitched edge to edge.
//! No host or JS types live here; [`api`] is the JSON-shaped contract that the WASM binding
//! (`wasm.rs`, wasm32 only) and the `dformer` CLI expose.
//!
//! - [`contour`]: the closed outline (Illustrator's PathPoint model).
//! - [`arclen`]: arc length and its inverse, relative `accuracy` ([`arclen::DEFAULT_ACCURACY`]).
//! - [`validate`]: input checks (degenerate outlines, self-intersection).
//! - [`measure`], [`normalize`], [`connect`]: the three editing operations.
//! - [`simulate`]: 3D form-finding of the glued D-form; [`form`]: its principal extents, and
//!   flat points (connectors) carried onto it.

pub mod api;
pub mod arclen;
pub mod connect;
pub mod contour;
pub mod error;
pub mod form;
pub mod libm_ext;
pub mod measure;
pub mod normalize;
pub mod order;
pub mod simulate;
pub mod svg;
pub mod validate;

#[cfg(target_arch = "wasm32")]
mod wasm;

pub use arclen::DEFAULT_ACCURACY;
pub use error::{Error, Result};
