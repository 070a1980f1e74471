// A self-collision disagreement page: frames of a mesh, each with the triangle pairs an engine
// missed (red, the referee finds them) and the ones it added (purple, the referee does not).
import { floats, uints } from './decode.js';
import { makeStage, meshOf } from './stage.js';
import { chooser, line, panel } from './ui.js';

const MESH = 0x8fb3e0, MISSED = 0xd62728, EXTRA = 0x9467bd;

function pairTriangles(x, tris, pairs) {
  const out = [];
  for (const [i, j] of pairs)
    for (const t of [i, j]) for (let c = 0; c < 3; ++c) out.push(...x.subarray(3 * tris[3 * t + c], 3 * tris[3 * t + c] + 3));
  return new Float32Array(out);
}

export function showFrames(data, container) {
  const stage = makeStage(container);
  const info = panel();
  line(info, 'file', data.file);
  const legend = line(info, 'colours', 'blue: mesh · red: pairs the engine missed · purple: pairs it added');
  legend.classList.add('legend');
  const tris = uints(data.triangles);
  const frames = data.frames || [];
  const view = (window.tecidoView = { kind: 'selfcollision', entry: 0, entries: frames.length });
  if (frames.length === 0) {
    line(info, 'note', 'no disagreement: nothing to draw');
    stage.render();
    return;
  }
  let framed = false;
  chooser(info, frames.map((f) => `${f.label} — ${f.engine}: ${f.missed.length} missed, ${f.extra.length} extra`), (k) => {
    for (const o of [...stage.scene.children]) if (!o.isLight) stage.scene.remove(o);
    const f = frames[k];
    const x = floats(f.positions);
    meshOf(stage, x, tris, MESH, { opacity: 0.55, offset: 2 });
    meshOf(stage, pairTriangles(x, tris, f.missed), null, MISSED, { offset: 0 });
    meshOf(stage, pairTriangles(x, tris, f.extra), null, EXTRA, { offset: 0 });
    info.querySelectorAll('.entry').forEach((n) => n.remove());
    line(info, 'frame', f.label, 'entry');
    line(info, 'engine', f.engine, 'entry');
    line(info, 'missed', f.missed.map((p) => `(${p[0]}, ${p[1]})`).join(' ') || 'none', 'entry');
    line(info, 'extra', f.extra.map((p) => `(${p[0]}, ${p[1]})`).join(' ') || 'none', 'entry');
    if (!framed) stage.frame(x), (framed = true);
    view.entry = k;
    stage.render();
  });
}
