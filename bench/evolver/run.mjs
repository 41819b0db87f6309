// Runs Surface Evolver on a datafile and command script and reads its printed lines back.
import { spawnSync } from 'node:child_process';
import { mkdtempSync, writeFileSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';

/** The Evolver executable on PATH (Debian's evolver-nox installs `evolver` and its -d/-ld/-q builds), or null. */
export function findEvolver() {
  for (const name of ['evolver', 'evolver-nox-d', 'evolver-nox']) {
    const r = spawnSync('sh', ['-c', `command -v ${name}`], { encoding: 'utf8' });
    if (r.status === 0 && r.stdout.trim()) return r.stdout.trim();
  }
  return null;
}

/**
 * Runs `evolver -x -i -f script datafile` (exit on error, keep the datafile's ids). Returns
 * `{ corners, stages, vertices, ms, log, timedOut }`: `F` lines (facet id and its corner ids),
 * `S` lines (kb, steps, energy, stretch, bend) and the vertices (id → position) printed before
 * the last `S` line. A run over `timeoutMs` is stopped and keeps its last complete stage.
 */
export function runEvolver(exe, text, commands, { timeoutMs = 600_000 } = {}) {
  const dir = mkdtempSync(join(tmpdir(), 'dformer-evolver-'));
  try {
    writeFileSync(join(dir, 'sheet.fe'), text);
    writeFileSync(join(dir, 'run.cmd'), commands);
    const t0 = performance.now();
    const r = spawnSync(exe, ['-x', '-i', '-f', 'run.cmd', 'sheet.fe'], {
      cwd: dir, input: 'quit\n', encoding: 'utf8', timeout: timeoutMs, killSignal: 'SIGKILL', maxBuffer: 1 << 28,
    });
    const ms = performance.now() - t0;
    const log = `${r.stdout ?? ''}${r.stderr ?? ''}`;
    // Vertices are printed before each stage's S line: keep those of the last complete stage.
    const corners = new Map(), stages = [];
    let vertices = new Map(), pending = new Map();
    for (const line of log.split('\n')) {
      const w = line.trim().split(/\s+/);
      if (w[0] === 'F' && w.length === 5) corners.set(+w[1], w.slice(2).map(Number));
      if (w[0] === 'V' && w.length === 5) pending.set(+w[1], w.slice(2).map(Number));
      if (w[0] === 'S' && w.length === 6) {
        stages.push({ kb: +w[1], steps: +w[2], energy: +w[3], stretch: +w[4], bend: +w[5] });
        [vertices, pending] = [pending, new Map()];
      }
    }
    const timedOut = r.error?.code === 'ETIMEDOUT' || r.signal === 'SIGTERM';
    if (r.error && !timedOut) throw new Error(`Surface Evolver did not run: ${r.error.message}`);
    return { corners, stages, vertices, ms, log, status: r.status, timedOut };
  } finally {
    rmSync(dir, { recursive: true, force: true });
  }
}
