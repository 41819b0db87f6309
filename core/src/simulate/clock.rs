//! A millisecond timer for `stats.ms` that works natively (`std::time::Instant`) and in wasm32,
//! where `Instant::now` panics: there it reads the host's `performance.now()` (falling back to
//! `Date.now()` where a host has no `performance`).

/// Started at construction; [`Timer::elapsed_ms`] reads the time since.
pub struct Timer {
    #[cfg(not(target_arch = "wasm32"))]
    start: std::time::Instant,
    #[cfg(target_arch = "wasm32")]
    start: f64,
}

#[cfg(target_arch = "wasm32")]
mod js {
    use wasm_bindgen::prelude::*;

    #[wasm_bindgen]
    extern "C" {
        #[wasm_bindgen(js_namespace = performance, js_name = now, catch)]
        fn performance_now() -> Result<f64, JsValue>;
        #[wasm_bindgen(js_namespace = Date, js_name = now)]
        fn date_now() -> f64;
    }

    pub fn now_ms() -> f64 {
        performance_now().unwrap_or_else(|_| date_now())
    }
}

impl Timer {
    pub fn start() -> Self {
        #[cfg(not(target_arch = "wasm32"))]
        return Timer { start: std::time::Instant::now() };
        #[cfg(target_arch = "wasm32")]
        return Timer { start: js::now_ms() };
    }

    /// Milliseconds since [`Timer::start`].
    pub fn elapsed_ms(&self) -> f64 {
        #[cfg(not(target_arch = "wasm32"))]
        return self.start.elapsed().as_secs_f64() * 1e3;
        #[cfg(target_arch = "wasm32")]
        return (js::now_ms() - self.start).max(0.0);
    }
}
