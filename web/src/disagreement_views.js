// The pages of the agreement suites' disagreement files: tritri (two triangles), plane (a
// segment and its bounded plane), ccd (a query animated over t in [0, 1]). The page's data is
// the file itself; one entry is shown at a time (chooser; the page's #k opens entry k).
import { makeStage, meshOf, linesOf, dot } from './stage.js';
import { chooser, line, panel, player, el } from './ui.js';
import { entryName, showEntry, lerp, flat } from './answers.js';

const A = 0x3b75c4, B = 0xe08a1e, HIT = 0xd62728, REF = 0x2ca02c, ENGINE = 0xff7f0e;

/// Clears the stage's objects but its lights.
export function clear(stage) {
  for (const o of [...stage.scene.children]) if (!o.isLight) stage.scene.remove(o);
}

function triangle(stage, pts, color) {
  meshOf(stage, flat(pts), null, color, { opacity: 0.7 });
  linesOf(stage, flat([pts[0], pts[1], pts[1], pts[2], pts[2], pts[0]]), color);
}

const LEGENDS = {
  tritri: 'blue: triangle a · orange: triangle b',
  plane: "blue: the bounded plane · black: the segment from its start (dot) · red: the engine's hit point · green: the referee's",
  ccd: "blue and red: the query at t · grey: the paths from t = 0 to 1 · green: where the referee says they first touch · orange: where the engine says",
};

/// The page of a disagreement file: the chooser over `list`, `draw(stage, entry, info)` on each
/// choice. `labels`: the legend, an entry's name in the chooser and its lines in the panel (by
/// default those of an agreement suite's entry: engine, its answer, the referee's).
export function setup(data, container, list, timeKey, draw, labels = {}) {
  const legend = labels.legend ?? LEGENDS[data.kind];
  const name = labels.name ?? ((e) => entryName(e, timeKey));
  const describe = labels.describe ?? ((info, e) => showEntry(info, e, timeKey));
  const stage = makeStage(container);
  const info = panel();
  line(info, 'file', data.file);
  line(info, 'colours', legend).classList.add('legend');
  line(info, 'entries', `${list.length} (choose one below)`);
  const view = (window.tecidoView = { kind: data.kind, entry: 0, entries: list.length });
  if (list.length === 0) {
    line(info, 'note', 'no disagreement: nothing to draw');
    stage.render();
    return;
  }
  chooser(info, list.map(name), (k) => {
    clear(stage);
    describe(info, list[k]);
    view.entry = k;
    draw(stage, list[k], info);
    stage.render();
  });
}

export function showTriTri(data, container) {
  setup(data, container, data.doc.pairs || [], null, (stage, e) => {
    triangle(stage, e.a, A);
    triangle(stage, e.b, B);
    stage.frame(flat([...e.a, ...e.b]));
  });
}

function norm(v) {
  const l = Math.hypot(v[0], v[1], v[2]) || 1;
  return [v[0] / l, v[1] / l, v[2] / l];
}

function cross(a, b) {
  return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
}

export function showPlane(data, container) {
  setup(data, container, data.doc.cases || [], 't', (stage, e) => {
    const p = e.plane, n = norm(p.normal), f = norm(p.forward), r = cross(n, f);
    const [hx, hy] = p.half_extents;
    const corner = (s, u) => [0, 1, 2].map((i) => p.position[i] + s * hx * f[i] + u * hy * r[i]);
    const c = [corner(-1, -1), corner(1, -1), corner(1, 1), corner(-1, 1)];
    meshOf(stage, flat([c[0], c[1], c[2], c[0], c[2], c[3]]), null, A, { opacity: 0.7 });
    linesOf(stage, flat([c[0], c[1], c[1], c[2], c[2], c[3], c[3], c[0]]), A);
    linesOf(stage, flat([e.from, e.to]), 0x222222);
    const len = Math.hypot(...[0, 1, 2].map((i) => e.to[i] - e.from[i])) || Math.max(hx, hy);
    dot(stage, e.from, len * 0.02, 0x222222);
    if (e.answer && e.answer.hit && typeof e.answer.t === 'number') dot(stage, lerp(e.from, e.to, e.answer.t), len * 0.03, HIT);
    if (e.referee && e.referee.hit && typeof e.referee.t === 'number') dot(stage, lerp(e.from, e.to, e.referee.t), len * 0.025, REF);
    stage.frame(flat([...c, e.from, e.to]));
  });
}

/// The query's primitives at time t: vertex-face (a point and a triangle) or edge-edge (two
/// segments). `ghost`: a colour to draw them thin in (a time of impact), else drawn solid.
function ccdAt(stage, e, t, ghost = null) {
  const q = [0, 1, 2, 3].map((i) => lerp(e.t0[i], e.t1[i], t));
  const scale = Math.max(...[1, 2, 3].map((i) => Math.hypot(...[0, 1, 2].map((c) => q[i][c] - q[0][c])))) || 1;
  if (e.kind === 'vertex-face') {
    dot(stage, q[0], scale * (ghost ? 0.015 : 0.03), ghost ?? HIT);
    if (!ghost) triangle(stage, [q[1], q[2], q[3]], A);
    else linesOf(stage, flat([q[1], q[2], q[2], q[3], q[3], q[1]]), ghost);
  } else {
    linesOf(stage, flat([q[0], q[1]]), ghost ?? HIT);
    linesOf(stage, flat([q[2], q[3]]), ghost ?? A);
  }
}

/// Where an answer says the primitives first touch, when it says they do.
function toiOf(a) {
  return a && a.hit && typeof a.toi === 'number' ? a.toi : null;
}

export function showCcd(data, container) {
  const steps = 1000;
  let current = null, slider = null;
  setup(data, container, data.doc.queries || [], 'toi', (stage, e, info) => {
    current = { stage, e };
    const all = flat([...e.t0, ...e.t1]);
    stage.frame(all);
    if (!slider) slider = player(info, steps, (k) => drawAt(k / steps), 60);
    toiButtons(info, e, (t) => slider.set(Math.round(t * steps)));
    slider.set(0);
  });
  function drawAt(t) {
    if (!current) return;
    const { stage, e } = current;
    clear(stage);
    // Grey trails from t = 0 to t = 1, the primitives now, and in green where the referee says they meet.
    linesOf(stage, flat([0, 1, 2, 3].flatMap((i) => [e.t0[i], e.t1[i]])), 0xbbbbbb);
    if (toiOf(e.referee) !== null) ccdAt(stage, e, toiOf(e.referee), REF);
    if (toiOf(e.answer) !== null) ccdAt(stage, e, toiOf(e.answer), ENGINE);
    ccdAt(stage, e, t);
    document.getElementById('frame-label').textContent = `t = ${t.toFixed(3)}`;
    window.tecidoView.t = t;
    stage.render();
  }
}

/// Buttons that move the slider to the referee's and the engine's time of impact.
function toiButtons(info, e, go) {
  info.querySelectorAll('.toi').forEach((n) => n.remove());
  const box = el('div', { class: 'toi' });
  for (const [who, a] of [["referee's toi (green)", e.referee], [`${e.engine}'s toi (orange)`, e.answer]]) {
    if (toiOf(a) === null) {
      box.append(el('span', { class: 'label' }, `${who}: none (miss) `));
      continue;
    }
    const b = el('button', { type: 'button' }, `${who} ${toiOf(a).toPrecision(6)}`);
    b.addEventListener('click', () => go(toiOf(a)));
    box.append(b);
  }
  info.append(box);
}
