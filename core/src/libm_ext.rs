//! The transcendental functions of the core, from the `libm` crate on every target.
//!
//! `f64::sin` and its kin call the platform's maths library: glibc's on Linux, the C runtime's
//! on Windows, Apple's on macOS, and in WebAssembly a port of musl's. They agree to an ulp or
//! so, not to the bit, and the form of a non-convex pair turns on last bits (its meshes decide
//! near-ties by exact predicates, [`crate::simulate::sheet`]): the same JSON input gave the
//! kidney with its mirror image at 5/16 of its perimeter 226,566 mm³ natively on Linux and
//! 226,184 mm³ in the browser (16 other pairs agreed to the bit). With the `libm` crate (the
//! same musl port) everywhere, the Inkscape extension's `dformer` on each system, the tests
//! and the panel compute the same bits. Square roots and the four operations are IEEE-exact on
//! every target and stay as they are; kurbo is built on `libm` too (`core/Cargo.toml`).
//!
//! Each method is the `std` one of the same name with `_m` appended.

/// `f64`'s transcendental functions, computed by `libm`.
pub trait LibmExt {
    fn sin_m(self) -> f64;
    fn cos_m(self) -> f64;
    fn tan_m(self) -> f64;
    fn asin_m(self) -> f64;
    fn acos_m(self) -> f64;
    fn atan_m(self) -> f64;
    fn atan2_m(self, x: f64) -> f64;
    fn sin_cos_m(self) -> (f64, f64);
    fn exp_m(self) -> f64;
    fn ln_m(self) -> f64;
    fn log10_m(self) -> f64;
    fn log2_m(self) -> f64;
    fn powf_m(self, e: f64) -> f64;
    fn hypot_m(self, y: f64) -> f64;
    fn cbrt_m(self) -> f64;
}

impl LibmExt for f64 {
    fn sin_m(self) -> f64 {
        libm::sin(self)
    }
    fn cos_m(self) -> f64 {
        libm::cos(self)
    }
    fn tan_m(self) -> f64 {
        libm::tan(self)
    }
    fn asin_m(self) -> f64 {
        libm::asin(self)
    }
    fn acos_m(self) -> f64 {
        libm::acos(self)
    }
    fn atan_m(self) -> f64 {
        libm::atan(self)
    }
    fn atan2_m(self, x: f64) -> f64 {
        libm::atan2(self, x)
    }
    fn sin_cos_m(self) -> (f64, f64) {
        libm::sincos(self)
    }
    fn exp_m(self) -> f64 {
        libm::exp(self)
    }
    fn ln_m(self) -> f64 {
        libm::log(self)
    }
    fn log10_m(self) -> f64 {
        libm::log10(self)
    }
    fn log2_m(self) -> f64 {
        libm::log2(self)
    }
    fn powf_m(self, e: f64) -> f64 {
        libm::pow(self, e)
    }
    fn hypot_m(self, y: f64) -> f64 {
        libm::hypot(self, y)
    }
    fn cbrt_m(self) -> f64 {
        libm::cbrt(self)
    }
}
