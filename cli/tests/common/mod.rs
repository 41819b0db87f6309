//! What the CLI's integration tests share: running the built `dformer` and keeping what it said.
#![allow(dead_code)]

use std::process::Command;

/// One run of `dformer`: whether it exited 0, and its output.
pub struct Run {
    pub ok: bool,
    pub stdout: String,
    pub stderr: String,
}

/// Runs the built `dformer` with `args`.
pub fn dformer(args: &[&str]) -> Run {
    let out = Command::new(env!("CARGO_BIN_EXE_dformer")).args(args).output().expect("dformer runs");
    Run { ok: out.status.success(), stdout: String::from_utf8_lossy(&out.stdout).into(), stderr: String::from_utf8_lossy(&out.stderr).into() }
}
