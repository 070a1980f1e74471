// The selfcollision suite's disagreement page: one engine's answer on one recorded frame of the
// cloth, the true pairs of triangles it missed in red, the pairs it reported that do not
// intersect in orange, the cloth pale. The page's data is the file with its arrays as base64
// (comparisons/suites/selfcollision/frame_disagreements.h).
import { floats, uints } from './decode.js';
import { meshOf, linesOf } from './stage.js';
import { line } from './ui.js';
import { setup } from './disagreement_views.js';

const CLOTH = 0x9fb8d8, MISSED = 0xd62728, EXTRA = 0xff7f0e;
const LEGEND =
  'pale blue: the cloth at that frame · red: pairs of triangles that intersect and the engine missed · orange: pairs the engine reported that do not intersect';

/// The two triangles of each pair ([[i, j], ...]) at positions x, as one unindexed position buffer.
function pairTriangles(x, tris, pairs) {
  const out = new Float32Array(pairs.length * 18);
  let w = 0;
  for (const p of pairs)
    for (const t of p)
      for (let c = 0; c < 3; ++c) {
        const v = tris[3 * t + c];
        out[w++] = x[3 * v], out[w++] = x[3 * v + 1], out[w++] = x[3 * v + 2];
      }
  return out;
}

/// The outlines of an unindexed triangle buffer, as line segments.
function outlines(buf) {
  const out = new Float32Array(buf.length * 2);
  let w = 0;
  for (let t = 0; t < buf.length; t += 9)
    for (const [a, b] of [[0, 1], [1, 2], [2, 0]]) {
      out.set(buf.subarray(t + 3 * a, t + 3 * a + 3), w);
      out.set(buf.subarray(t + 3 * b, t + 3 * b + 3), w + 3);
      w += 6;
    }
  return out;
}

function countText(listed, total) {
  return listed === total ? `${total} pairs` : `${listed} of ${total} pairs drawn (the file keeps the first ${listed})`;
}

function describe(info, e) {
  info.querySelectorAll('.entry').forEach((n) => n.remove());
  line(info, 'id', e.id, 'entry');
  line(info, 'engine', e.engine ?? '?', 'entry');
  line(info, 'frame', `${e.frame} of ${e.source}, t = ${Number(e.time).toPrecision(6)} s`, 'entry');
  line(info, 'missed (red)', countText(e.missed.length, e.missed_count), 'entry');
  line(info, 'extra (orange)', countText(e.extra.length, e.extra_count), 'entry');
}

export function showSelfCollision(data, container) {
  const doc = data.doc;
  const sources = new Map();
  for (const s of doc.sources || [])
    sources.set(s.source, { tris: uints(s.triangles), frames: new Map((s.frames || []).map((f) => [f.frame, floats(f.x)])) });
  const draw = (stage, e) => {
    const src = sources.get(e.source);
    const x = src && src.frames.get(e.frame);
    // What was drawn, counted from the buffers built (the browser tests compare it with the file).
    const drawn = { missed: 0, extra: 0 };
    if (x) {
      meshOf(stage, x, src.tris, CLOTH, { opacity: 0.35, offset: 2 });
      for (const [key, colour] of [['missed', MISSED], ['extra', EXTRA]]) {
        const buf = pairTriangles(x, src.tris, e[key] || []);
        meshOf(stage, buf, null, colour, { offset: 0 });
        linesOf(stage, outlines(buf), colour);
        drawn[key] = buf.length / 18;
      }
      stage.frame(x);
    }
    window.tecidoView.drawn = drawn;
  };
  setup(data, container, doc.entries || [], null, draw, {
    legend: LEGEND,
    name: (e) => `${e.id} — ${e.missed_count} missed, ${e.extra_count} extra`,
    describe,
  });
}
