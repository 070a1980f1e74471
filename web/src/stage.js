// The 3-D stage every view shares: renderer, camera, orbit controls, lights, a render on demand.
import * as THREE from 'three';
import { OrbitControls } from 'three/examples/jsm/controls/OrbitControls.js';

export function makeStage(container) {
  // preserveDrawingBuffer: the canvas can be read back (a person's "save image", the browser tests).
  const renderer = new THREE.WebGLRenderer({ antialias: true, preserveDrawingBuffer: true });
  renderer.setPixelRatio(window.devicePixelRatio || 1);
  renderer.setClearColor(0xf4f4f0);
  container.append(renderer.domElement);
  const scene = new THREE.Scene();
  const camera = new THREE.PerspectiveCamera(40, 1, 1e-4, 1e4);
  camera.up.set(0, 1, 0);
  const controls = new OrbitControls(camera, renderer.domElement);
  scene.add(new THREE.HemisphereLight(0xffffff, 0x666666, 2.2));
  const sun = new THREE.DirectionalLight(0xffffff, 1.5);
  sun.position.set(1, 2, 1.5);
  scene.add(sun);
  const stage = {
    THREE,
    scene,
    camera,
    renderer,
    render() {
      renderer.render(scene, camera);
    },
    /// Points the camera at the box holding every xyz of the Float32Arrays `arrays`.
    frame(...arrays) {
      const lo = [Infinity, Infinity, Infinity], hi = [-Infinity, -Infinity, -Infinity];
      for (const points of arrays)
        for (let i = 0; i + 2 < points.length; i += 3)
          for (let c = 0; c < 3; ++c) {
            const v = points[i + c];
            if (v < lo[c]) lo[c] = v;
            if (v > hi[c]) hi[c] = v;
          }
      const box = new THREE.Box3(new THREE.Vector3(...lo), new THREE.Vector3(...hi));
      if (box.isEmpty()) box.set(new THREE.Vector3(-1, -1, -1), new THREE.Vector3(1, 1, 1));
      const c = box.getCenter(new THREE.Vector3());
      const r = Math.max(box.getSize(new THREE.Vector3()).length() / 2, 1e-3);
      controls.target.copy(c);
      camera.position.copy(c).add(new THREE.Vector3(0.9, 0.6, 1.6).normalize().multiplyScalar(r * 3));
      camera.near = r / 100;
      camera.far = r * 100;
      camera.updateProjectionMatrix();
      controls.update();
    },
  };
  const resize = () => {
    const w = container.clientWidth || 800;
    const h = container.clientHeight || 600;
    renderer.setSize(w, h);
    camera.aspect = w / h;
    camera.updateProjectionMatrix();
    stage.render();
  };
  window.addEventListener('resize', resize);
  controls.addEventListener('change', () => stage.render());
  resize();
  return stage;
}

/// A triangle mesh over `positions` (Float32Array xyz, shared or copied) and `index` (Uint32Array).
export function meshOf(stage, positions, index, color, opts = {}) {
  const { THREE } = stage;
  const g = new THREE.BufferGeometry();
  g.setAttribute('position', new THREE.BufferAttribute(positions, 3));
  if (index) g.setIndex(new THREE.BufferAttribute(index, 1));
  g.computeVertexNormals();
  const m = new THREE.MeshStandardMaterial({
    color,
    side: THREE.DoubleSide,
    flatShading: true,
    transparent: (opts.opacity ?? 1) < 1,
    opacity: opts.opacity ?? 1,
    polygonOffset: true,
    polygonOffsetFactor: opts.offset ?? 1,
    polygonOffsetUnits: opts.offset ?? 1,
  });
  const mesh = new THREE.Mesh(g, m);
  stage.scene.add(mesh);
  return mesh;
}

/// Line segments over `positions` (xyz pairs); `colors` (rgb per vertex) optional.
export function linesOf(stage, positions, color, colors = null) {
  const { THREE } = stage;
  const g = new THREE.BufferGeometry();
  g.setAttribute('position', new THREE.BufferAttribute(positions, 3));
  if (colors) g.setAttribute('color', new THREE.BufferAttribute(colors, 3));
  const m = new THREE.LineBasicMaterial(colors ? { vertexColors: true } : { color });
  const lines = new THREE.LineSegments(g, m);
  stage.scene.add(lines);
  return lines;
}

/// A small sphere marking a point.
export function dot(stage, p, radius, color) {
  const { THREE } = stage;
  const s = new THREE.Mesh(new THREE.SphereGeometry(radius, 16, 12), new THREE.MeshStandardMaterial({ color }));
  s.position.set(p[0], p[1], p[2]);
  stage.scene.add(s);
  return s;
}
