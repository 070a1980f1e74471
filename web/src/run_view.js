// `tecido run --out DIR`'s page: the cloth (or particles) and the obstacles over the recorded
// frames, the triangle pairs in self-contact at each frame in red, springs through an obstacle in
// orange. Positions arrive as one Float32Array (frames x nodes x 3), copied into the drawn buffer.
import { floats, uints, perFrame } from './decode.js';
import { makeStage, meshOf, linesOf } from './stage.js';
import { line, player, panel } from './ui.js';

const CLOTH = 0x5b8fd6, CONTACT = 0xd62728, THROUGH = [1.0, 0.5, 0.05], OBSTACLE = 0x9a9a9a;

function obstacleMeshes(stage, data) {
  return (data.obstacles || []).map((o) => {
    const all = floats(o.positions);
    const count = o.vertices * 3;
    const pos = all.slice(0, count);
    const mesh = meshOf(stage, pos, uints(o.triangles), OBSTACLE, { opacity: 0.75, offset: 2 });
    return { mesh, all, count, moving: all.length > count };
  });
}

/// The triangles of frame f's contact pairs as one unindexed position buffer.
function contactTriangles(x, tris, pairs) {
  const out = new Float32Array(pairs.length * 9);
  let w = 0;
  for (const t of pairs)
    for (let c = 0; c < 3; ++c) {
      const v = tris[3 * t + c];
      out[w++] = x[3 * v], out[w++] = x[3 * v + 1], out[w++] = x[3 * v + 2];
    }
  return out;
}

function springSegments(x, springs, list) {
  const out = new Float32Array(list.length * 6);
  let w = 0;
  for (const s of list)
    for (let e = 0; e < 2; ++e) {
      const v = springs[2 * s + e];
      out[w++] = x[3 * v], out[w++] = x[3 * v + 1], out[w++] = x[3 * v + 2];
    }
  return out;
}

export function showRun(data, container) {
  const stage = makeStage(container);
  const { THREE } = stage;
  const n3 = data.nodes * 3;
  const all = floats(data.positions);
  const frames = data.frames;
  const tris = uints(data.triangles);
  const springs = uints(data.springs);
  const cOff = uints(data.contacts.offsets), cPairs = uints(data.contacts.pairs);
  const sOff = uints(data.through.offsets), sList = uints(data.through.springs);
  const x = all.slice(0, n3);
  let cloth;
  if (tris.length > 0) cloth = meshOf(stage, x, tris, CLOTH);
  else {
    const g = new THREE.BufferGeometry();
    g.setAttribute('position', new THREE.BufferAttribute(x, 3));
    cloth = new THREE.Points(g, new THREE.PointsMaterial({ color: CLOTH, size: 4, sizeAttenuation: false }));
    stage.scene.add(cloth);
  }
  const obstacles = obstacleMeshes(stage, data);
  const contact = meshOf(stage, new Float32Array(0), null, CONTACT, { offset: 0 });
  const through = linesOf(stage, new Float32Array(0), null, new Float32Array(0));
  const info = panel();
  line(info, 'scene', data.title);
  const status = line(info, 'frame', '');
  const counts = line(info, 'contacts', '');
  const legend = line(info, 'colours', 'blue: cloth · red: triangles in self-contact · orange: springs through an obstacle · grey: obstacles');
  legend.classList.add('legend');
  const view = (window.tecidoView = { kind: 'run', frame: 0, frames, positions: () => Array.from(cloth.geometry.attributes.position.array.subarray(0, 30)) });
  const show = (f) => {
    const xf = all.subarray(f * n3, (f + 1) * n3);
    const pa = cloth.geometry.attributes.position;
    pa.array.set(xf);
    pa.needsUpdate = true;
    if (tris.length > 0) cloth.geometry.computeVertexNormals();
    for (const o of obstacles)
      if (o.moving) {
        const a = o.mesh.geometry.attributes.position;
        a.array.set(o.all.subarray(f * o.count, (f + 1) * o.count));
        a.needsUpdate = true;
        o.mesh.geometry.computeVertexNormals();
      }
    const pairs = perFrame(cOff, cPairs, f, 2);
    const ts = new Set(pairs);
    contact.geometry.setAttribute('position', new THREE.BufferAttribute(contactTriangles(xf, tris, ts), 3));
    contact.geometry.computeVertexNormals();
    const list = perFrame(sOff, sList, f, 1);
    const seg = springSegments(xf, springs, list);
    const col = new Float32Array(seg.length);
    for (let i = 0; i < col.length; i += 3) col.set(THROUGH, i);
    through.geometry.setAttribute('position', new THREE.BufferAttribute(seg, 3));
    through.geometry.setAttribute('color', new THREE.BufferAttribute(col, 3));
    status.lastChild.textContent = `${f + 1} of ${frames}, step ${data.steps[f]}, t = ${data.times[f].toPrecision(6)} s`;
    counts.lastChild.textContent = `${pairs.length / 2} triangle pairs in self-contact, ${list.length} springs through an obstacle`;
    view.frame = f;
    stage.render();
  };
  stage.frame(all, ...obstacles.map((o) => o.all));
  const p = player(info, frames - 1, show);
  show(0);
  return p;
}
