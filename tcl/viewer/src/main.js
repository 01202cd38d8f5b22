// SPDX-License-Identifier: MIT
// The DABS post-processor page: the deformed model in a three.js scene (members with their real
// size, bearings coloured by shear strain, contact faces lit while closed, gaps printed at the
// joints, the ground acceleration), views 3D / plan / elevation, a time slider, play/pause, a
// magnification control, and uPlot time histories with a cursor at the current time.
import * as THREE from 'three';
import { OrbitControls } from 'three/examples/jsm/controls/OrbitControls.js';
import uPlot from 'uplot';
import 'uplot/dist/uPlot.min.css';
import { readData } from './data.js';
import { strainColor, kStrainScale, kDesignStrain, kFailureStrain } from './colors.js';

const kColors = {
  background: 0xffffff,
  node: 0x00b050,
  beam: 0x1f4e9c,
  member: 0x8a9bb0,          // girders and piers drawn as solids
  block: 0xb8b2a6,           // caps and footings (concrete)
  link: 0x555555,
  failedEdge: 0x000000,
  contactOpen: 0xc8c8c8,
  contactClosed: 0xff00aa,
  ground: 0x2e7d32,
};
const kNodePointSize = 7;     // px
const kBearingSizeRatio = 0.01;  // bearing pad edge / model size when no -bearingPad was given
const kTargetDeformationRatio = 0.1;  // auto magnification: peak drawn displacement / model size
const kGroundArrowRatio = 0.12;  // ground arrow length at the peak acceleration / model size
const kLabelMargin = 2;       // px kept free between two gap labels
const kHoverRadius = 24;      // px: a joint within this distance of the pointer shows its label
const kFitMargin = 0.9;       // first views: the model's projected extent / the canvas, at most

const hex = (c) => '#' + c.toString(16).padStart(6, '0');

/** Rounds down to 1, 2 or 5 times a power of ten. */
function niceNumber(x) {
  if (!(x > 0) || !isFinite(x)) return 1;
  const p = Math.pow(10, Math.floor(Math.log10(x)));
  const m = x / p;
  return (m >= 5 ? 5 : m >= 2 ? 2 : 1) * p;
}

function main() {
  const data = readData(document.getElementById('dabs-data').textContent);
  const title = data.title || 'DABS';
  document.title = title + ' - DABS viewer';
  document.getElementById('title').textContent = title;

  // ---- geometry ---------------------------------------------------------------------------
  const nNodes = data.nodes.length;
  const box = new THREE.Box3();
  for (const c of data.coords) box.expandByPoint(new THREE.Vector3(c[0], c[1], c[2]));
  if (nNodes === 0) box.set(new THREE.Vector3(-1, -1, -1), new THREE.Vector3(1, 1, 1));
  const center = box.getCenter(new THREE.Vector3());
  const size = Math.max(box.getSize(new THREE.Vector3()).length(), 1e-9);
  let peak = 0;
  for (const d of data.disp)
    for (let f = 0; f < data.frames; ++f)
      peak = Math.max(peak, Math.hypot(d[0][f], d[1][f], d[2][f]));
  // With contact the true scale is the honest one (magnified, touching faces would overlap).
  let magnification = data.contacts.length > 0 ? 1 :
    peak > 0 ? niceNumber((kTargetDeformationRatio * size) / peak) : 1;

  const scene = new THREE.Scene();
  scene.background = new THREE.Color(kColors.background);
  scene.add(new THREE.AmbientLight(0xffffff, 0.9));
  const sun = new THREE.DirectionalLight(0xffffff, 1.4);
  scene.add(sun);
  const zUp = data.ndm === 3;
  const camera = new THREE.PerspectiveCamera(35, 1, size * 1e-4, size * 100);
  if (zUp) { camera.up.set(0, 0, 1); sun.position.set(1, -2, 3); } else { sun.position.set(1, 2, 3); }

  const host = document.getElementById('scene');
  const renderer = new THREE.WebGLRenderer({ antialias: true, preserveDrawingBuffer: true });
  renderer.setPixelRatio(window.devicePixelRatio || 1);
  host.insertBefore(renderer.domElement, host.firstChild);
  const controls = new OrbitControls(camera, renderer.domElement);

  const statusOf = new Map(data.contacts.map((c) => [c.tag, c]));
  const bearingOf = new Map(data.bearings.map((b) => [b.tag, b]));
  const segments = { beam: [], link: [] };
  const solids = [];
  const bearings = [];
  const faces = new Map();   // contact target faces by their sorted node tags
  const contacts = [];
  for (const e of data.elements) {
    const idx = e.nodes.map((t) => data.nodeIndex.get(t));
    if (idx.some((i) => i === undefined)) continue;
    if (e.kind === 'beam' && e.shape.length >= 6 && idx.length === 2) {
      solids.push({ tag: e.tag, idx, outline: e.shape });
    } else if (e.kind === 'beam' || e.kind === 'link') {
      for (let k = 0; k + 1 < idx.length; ++k) segments[e.kind].push(idx[k], idx[k + 1]);
    } else if (e.kind === 'bearing') {
      const b = bearingOf.get(e.tag) || {};
      bearings.push({ tag: e.tag, idx, pad: e.shape.length === 2 ? e.shape : null, damage: b.damage, strain: b.strain });
    } else if (e.kind === 'contact') {
      const c = statusOf.get(e.tag) || {};
      const key = e.nodes.slice(1).sort((a, b) => a - b).join(',');
      if (!faces.has(key)) faces.set(key, { idx: idx.slice(1), contacts: [] });
      const contact = { tag: e.tag, idx, status: c.status, gap: c.gap, force: c.force, face: faces.get(key) };
      faces.get(key).contacts.push(contact);
      contacts.push(contact);
    }
  }
  const position = new Float32Array(3 * nNodes);  // drawn node positions

  // Beams without a section and links: line segments.
  const lineSets = [];
  for (const kind of ['beam', 'link']) {
    const pairs = segments[kind];
    if (pairs.length === 0) continue;
    const geometry = new THREE.BufferGeometry();
    geometry.setAttribute('position', new THREE.BufferAttribute(new Float32Array(3 * pairs.length), 3));
    const lines = new THREE.LineSegments(geometry, new THREE.LineBasicMaterial({ color: kColors[kind] }));
    lines.frustumCulled = false;
    scene.add(lines);
    lineSets.push({ pairs, geometry });
  }

  // Members with a section: the outline swept between the two end nodes (sides and end caps).
  const memberMaterial = new THREE.MeshLambertMaterial({ color: kColors.member, flatShading: true, transparent: true, opacity: 1 });
  for (const s of solids) {
    const n = s.outline.length / 2;
    const pos = new Float32Array(3 * 2 * n);
    const index = [];
    for (let k = 0; k < n; ++k) {
      const a = k, b = (k + 1) % n;
      index.push(a, b, n + b, a, n + b, n + a);
    }
    for (let k = 1; k + 1 < n; ++k) index.push(0, k + 1, k, n, n + k, n + k + 1);
    const geometry = new THREE.BufferGeometry();
    geometry.setAttribute('position', new THREE.BufferAttribute(pos, 3));
    geometry.setIndex(index);
    s.geometry = geometry;
    const mesh = new THREE.Mesh(geometry, memberMaterial);
    mesh.frustumCulled = false;
    scene.add(mesh);
  }

  // Blocks at nodes (caps, footings).
  const blockMaterial = new THREE.MeshLambertMaterial({ color: kColors.block, transparent: true, opacity: 1 });
  const blocks = data.blocks.filter((b) => data.nodeIndex.has(b.node)).map((b) => {
    const mesh = new THREE.Mesh(new THREE.BoxGeometry(b.size[0], b.size[1], b.size[2]), blockMaterial);
    scene.add(mesh);
    return { idx: data.nodeIndex.get(b.node), dz: b.dz, mesh };
  });

  // Bearing pads: a box whose bottom face follows node i and top face node j (so shear shows).
  const defaultPad = kBearingSizeRatio * size;
  const edgeMaterial = new THREE.LineBasicMaterial({ color: kColors.failedEdge });
  for (const b of bearings) {
    const geometry = new THREE.BoxGeometry(1, 1, 1);
    b.base = Float32Array.from(geometry.attributes.position.array);
    b.geometry = geometry;
    b.mesh = new THREE.Mesh(geometry, new THREE.MeshLambertMaterial({ color: 0xffffff }));
    b.mesh.frustumCulled = false;
    scene.add(b.mesh);
    const edges = new THREE.EdgesGeometry(new THREE.BoxGeometry(1, 1, 1));
    b.edgeBase = Float32Array.from(edges.attributes.position.array);
    b.edges = new THREE.LineSegments(edges, edgeMaterial);
    b.edges.frustumCulled = false;
    scene.add(b.edges);
  }

  // Contact target faces: quads lit while any of their contacts is closed.
  const faceList = [...faces.values()];
  for (const f of faceList) {
    const geometry = new THREE.BufferGeometry();
    geometry.setAttribute('position', new THREE.BufferAttribute(new Float32Array(12), 3));
    geometry.setIndex([0, 1, 2, 0, 2, 3]);
    f.geometry = geometry;
    f.mesh = new THREE.Mesh(geometry, new THREE.MeshBasicMaterial({
      color: kColors.contactOpen, side: THREE.DoubleSide, polygonOffset: true,
      polygonOffsetFactor: -2, polygonOffsetUnits: -8, transparent: true, opacity: 0.9 }));
    f.mesh.frustumCulled = false;
    scene.add(f.mesh);
  }

  const pointGeometry = new THREE.BufferGeometry();
  pointGeometry.setAttribute('position', new THREE.BufferAttribute(position, 3));
  const points = new THREE.Points(pointGeometry, new THREE.PointsMaterial({
    color: kColors.node, size: kNodePointSize, sizeAttenuation: false, depthTest: false, transparent: true }));
  // transparent too, so that it is drawn after the (transparent-capable) members: renderOrder
  // sorts within the transparent pass
  points.renderOrder = 10;
  points.frustumCulled = false;
  points.visible = false;
  scene.add(points);

  // Ground acceleration: the vector of the UniformExcitation patterns, an arrow at the ground.
  const groundVector = (f) => {
    const a = [0, 0, 0];
    for (const g of data.ground) a[g.dof] += g.accel[f];
    return a;
  };
  let groundPeak = 0;
  let groundAxis = [1, 0, 0];
  for (let f = 0; f < data.frames && data.ground.length; ++f) {
    const a = groundVector(f);
    const m = Math.hypot(a[0], a[1], a[2]);
    if (m > groundPeak) { groundPeak = m; groundAxis = a.map((v) => v / m); }
  }
  const groundOrigin = new THREE.Vector3(box.min.x - 0.05 * size, box.min.y - 0.1 * size, box.min.z);
  const groundArrow = new THREE.ArrowHelper(new THREE.Vector3(1, 0, 0), groundOrigin, 1, kColors.ground);
  groundArrow.visible = data.ground.length > 0;
  scene.add(groundArrow);
  if (data.ground.length > 0) {
    // the line of the motion through the arrow's origin, both ways
    const axis = new THREE.Vector3(...groundAxis).multiplyScalar(kGroundArrowRatio * size);
    const g = new THREE.BufferGeometry().setFromPoints([groundOrigin.clone().sub(axis), groundOrigin.clone().add(axis)]);
    scene.add(new THREE.Line(g, new THREE.LineDashedMaterial({ color: kColors.ground, dashSize: 0.01 * size, gapSize: 0.01 * size })).computeLineDistances());
  }

  // ---- overlay labels (gaps, failed bearings, ground) ---------------------------------------
  const overlay = document.getElementById('overlay');
  const makeLabel = (cls) => { const d = document.createElement('div'); d.className = 'label ' + cls; overlay.appendChild(d); return d; };
  const gaps = data.gaps.filter((g) => data.nodeIndex.has(g.a) && data.nodeIndex.has(g.b)).map((g) => ({
    ...g, ia: data.nodeIndex.get(g.a), ib: data.nodeIndex.get(g.b), el: makeLabel('gap') }));
  gaps.forEach((g, k) => { g.preferBelow = k % 2 === 1; g.contacts = []; g.dx = g.dy = 0; });
  // each contact belongs to the nearest joint (its contactor to the joint's midpoint)
  for (const c of contacts) {
    let best = null;
    let bestD = Infinity;
    for (const g of gaps) {
      const a = data.coords[g.ia];
      const b = data.coords[g.ib];
      const p = data.coords[c.idx[0]];
      const d = Math.hypot(p[0] - 0.5 * (a[0] + b[0]), p[1] - 0.5 * (a[1] + b[1]), p[2] - 0.5 * (a[2] + b[2]));
      if (d < bestD) { bestD = d; best = g; }
    }
    if (best) best.contacts.push(c);
  }
  for (const b of bearings) b.label = makeLabel('failed');
  const groundLabel = document.getElementById('ground');

  // ---- legend -------------------------------------------------------------------------------
  const legend = document.getElementById('legend');
  const rows = [];
  if (solids.length) rows.push(['girder / pier (section size)', kColors.member]);
  if (blocks.length) rows.push(['cap / footing', kColors.block]);
  if (segments.beam.length) rows.push(['beam (no section given)', kColors.beam]);
  if (segments.link.length) rows.push(['link / device', kColors.link]);
  if (faceList.length) rows.push(['contact face open', kColors.contactOpen], ['contact face closed', kColors.contactClosed]);
  if (data.ground.length) rows.push(['ground acceleration', kColors.ground]);
  legend.innerHTML = rows.map(([name, c]) => `<div><span style="background:${hex(c)}"></span>${name}</div>`).join('');
  const scaleBox = document.getElementById('strainscale');
  if (bearings.length) {
    const stops = [];
    for (let k = 0; k <= 20; ++k) {
      const s = (k / 20) * kStrainScale;
      stops.push(`${strainColor(s)} ${(100 * k / 20).toFixed(1)}%`);
    }
    const tick = (s, text) => `<i style="left:${(100 * s / kStrainScale).toFixed(1)}%">${text}</i>`;
    scaleBox.innerHTML = `<div>bearing shear strain (black edges: failed)</div><div class="bar" style="background:linear-gradient(to right, ${stops.join(',')})">` +
      tick(0, '0') + tick(1, '100%') + tick(2, '200%') + tick(kDesignStrain, '250%') + tick(kFailureStrain, '300%') + '</div>';
  } else {
    scaleBox.style.display = 'none';
  }

  // ---- state and drawing --------------------------------------------------------------------
  let frame = 0;
  const drawn = (i, f) => {
    const c = data.coords[i];
    const d = data.disp[i];
    return [c[0] + magnification * d[0][f], c[1] + magnification * d[1][f], c[2] + magnification * d[2][f]];
  };
  const tmpA = new THREE.Vector3();
  const tmpB = new THREE.Vector3();
  const ex = new THREE.Vector3();
  const ey = new THREE.Vector3();
  const ez = new THREE.Vector3();
  const zRef = new THREE.Vector3(0, 0, 1);
  const xRef = new THREE.Vector3(1, 0, 0);
  const closedNow = (c) => c.status !== undefined && c.status !== null && c.status[frame] > 0;
  function place() {
    for (let i = 0; i < nNodes; ++i) position.set(drawn(i, frame), 3 * i);
    pointGeometry.attributes.position.needsUpdate = true;
    for (const set of lineSets) {
      const a = set.geometry.attributes.position.array;
      set.pairs.forEach((i, k) => a.set(position.subarray(3 * i, 3 * i + 3), 3 * k));
      set.geometry.attributes.position.needsUpdate = true;
    }
    // Members: local x along the member, local y = zRef x x (zRef = Z, or X for vertical members),
    // local z = x x y; as OpenSees' vecxz for horizontal girders with vecxz = Z.
    for (const s of solids) {
      tmpA.fromArray(position, 3 * s.idx[0]);
      tmpB.fromArray(position, 3 * s.idx[1]);
      ex.subVectors(tmpB, tmpA).normalize();
      const ref = Math.abs(ex.z) > 0.9 ? xRef : zRef;
      ey.crossVectors(ref, ex).normalize();
      ez.crossVectors(ex, ey);
      const n = s.outline.length / 2;
      const p = s.geometry.attributes.position.array;
      for (let end = 0; end < 2; ++end) {
        const o = end ? tmpB : tmpA;
        for (let k = 0; k < n; ++k) {
          const y = s.outline[2 * k];
          const z = s.outline[2 * k + 1];
          const j = 3 * (end * n + k);
          p[j] = o.x + y * ey.x + z * ez.x;
          p[j + 1] = o.y + y * ey.y + z * ez.y;
          p[j + 2] = o.z + y * ey.z + z * ez.z;
        }
      }
      s.geometry.attributes.position.needsUpdate = true;
      s.geometry.computeVertexNormals();
    }
    for (const b of blocks) { b.mesh.position.fromArray(position, 3 * b.idx); b.mesh.position.z += b.dz; }
    for (const b of bearings) {
      tmpA.fromArray(position, 3 * b.idx[0]);
      tmpB.fromArray(position, 3 * b.idx[b.idx.length - 1]);
      const lx = b.pad ? b.pad[0] : defaultPad;
      const ly = b.pad ? b.pad[1] : defaultPad;
      // unit box vertex (x, y, z in -0.5..0.5): bottom (z < 0) at node i, top at node j
      const shape = (src, dst) => {
        for (let k = 0; k < src.length; k += 3) {
          const o = src[k + 2] < 0 ? tmpA : tmpB;
          dst[k] = o.x + lx * src[k];
          dst[k + 1] = o.y + ly * src[k + 1];
          dst[k + 2] = o.z;
        }
      };
      shape(b.base, b.geometry.attributes.position.array);
      b.geometry.attributes.position.needsUpdate = true;
      b.geometry.computeVertexNormals();
      shape(b.edgeBase, b.edges.geometry.attributes.position.array);
      b.edges.geometry.attributes.position.needsUpdate = true;
      const strain = b.strain ? b.strain[frame] : 0;
      b.mesh.material.color.set(strainColor(strain));
      const failed = b.damage ? b.damage[frame] >= 2 : false;
      b.failed = failed;
      b.edges.visible = failed;
      b.mid = tmpA.clone().add(tmpB).multiplyScalar(0.5);
    }
    for (const f of faceList) {
      const p = f.geometry.attributes.position.array;
      f.idx.forEach((i, k) => p.set(position.subarray(3 * i, 3 * i + 3), 3 * k));
      f.geometry.attributes.position.needsUpdate = true;
      f.closed = f.contacts.some(closedNow);
      f.mesh.material.color.setHex(f.closed ? kColors.contactClosed : kColors.contactOpen);
    }
    if (data.ground.length) {
      const a = groundVector(frame);
      const m = Math.hypot(a[0], a[1], a[2]);
      groundArrow.visible = m > 1e-12 * (groundPeak || 1);
      if (groundArrow.visible) {
        groundArrow.setDirection(new THREE.Vector3(a[0] / m, a[1] / m, a[2] / m));
        const len = kGroundArrowRatio * size * m / groundPeak;
        groundArrow.setLength(len, Math.min(0.3 * len, 0.02 * size), Math.min(0.15 * len, 0.01 * size));
      }
      const deg = (Math.atan2(groundAxis[1], groundAxis[0]) * 180) / Math.PI;
      groundLabel.textContent = `ground acceleration ${m.toFixed(2)} m/s² (X ${a[0].toFixed(2)}, Y ${a[1].toFixed(2)}); ` +
        `motion along ${deg.toFixed(0)}° from X, peak ${groundPeak.toFixed(2)} m/s²`;
    }
  }

  /** Screen position (CSS px relative to the scene) of a model point. */
  const vec = new THREE.Vector3();
  function toScreen(p) {
    vec.copy(p).project(camera);
    const r = renderer.domElement.getBoundingClientRect();
    return { x: (vec.x + 1) / 2 * r.width, y: (1 - vec.y) / 2 * r.height, visible: vec.z < 1 };
  }
  // Gap labels never overlap: at each drawing the joints are ranked (the one under the pointer,
  // then the pinned ones, then closed joints, then by the size of the relative displacement), and
  // each label is shown on its preferred side, else the other side (moved sideways into the canvas), only if its box intersects no
  // box already shown; the others appear on hover or click.
  let hovered = null;
  const pinned = new Set();
  const rank = (g) => (g === hovered ? 3e30 : 0) + (pinned.has(g) ? 2e30 : 0) + (g.closed ? 1e30 : 0) + Math.hypot(g.dx, g.dy);
  function placeLabels() {
    for (const g of gaps) {
      const d = (i, c) => data.disp[i][c][frame];
      const dx = d(g.ib, 0) - d(g.ia, 0);
      const dy = d(g.ib, 1) - d(g.ia, 1);
      g.dx = dx;
      g.dy = dy;
      let text = `${g.label}: ${dx >= 0 ? '+' : ''}${dx.toFixed(3)} m long., ${dy >= 0 ? '+' : ''}${dy.toFixed(3)} m trans.`;
      const withGap = g.contacts.filter((c) => c.gap);
      g.closed = false;
      if (withGap.length) {
        const clear = Math.min(...withGap.map((c) => c.gap[frame]));
        text += clear > 0 ? `; clear gap ${clear.toFixed(3)} m` : '; in contact';
        g.closed = clear <= 0;
      }
      g.el.textContent = text;
      tmpA.fromArray(position, 3 * g.ia).add(tmpB.fromArray(position, 3 * g.ib)).multiplyScalar(0.5);
      const s = toScreen(tmpA);
      g.x = s.x;
      g.y = s.y;
      g.onScreen = s.visible;
      g.el.style.left = `${s.x}px`;
      g.el.style.top = `${s.y}px`;
      g.el.style.display = '';
      g.el.style.visibility = 'hidden';
    }
    // one layout for all the sizes, then the boxes (the CSS transforms of .label and .below)
    for (const g of gaps) { g.w = g.el.offsetWidth; g.h = g.el.offsetHeight; }
    const shown = [];
    const canvasW = renderer.domElement.getBoundingClientRect().width;
    const overlaps = (r) => shown.some((q) => r.left < q.right + kLabelMargin && q.left < r.right + kLabelMargin &&
      r.top < q.bottom + kLabelMargin && q.top < r.bottom + kLabelMargin);
    for (const g of [...gaps].sort((a, b) => rank(b) - rank(a))) {
      let box = null;
      if (g.onScreen) {
        for (const below of g.preferBelow ? [true, false] : [false, true]) {
          const top = below ? g.y + 0.6 * g.h : g.y - 1.3 * g.h;
          const dxIn = Math.max(0.5 * g.w - g.x, 0) + Math.min(canvasW - 0.5 * g.w - g.x, 0);
          const r = { left: g.x + dxIn - 0.5 * g.w, right: g.x + dxIn + 0.5 * g.w, top, bottom: top + g.h, below, dxIn };
          if (!overlaps(r)) { box = r; break; }
        }
      }
      g.el.classList.toggle('below', box ? box.below : g.preferBelow);
      g.el.classList.toggle('above', box ? !box.below : !g.preferBelow);
      g.el.classList.toggle('hover', g === hovered);
      g.el.style.visibility = '';
      g.el.style.display = box ? '' : 'none';
      if (box) g.el.style.left = `${g.x + box.dxIn}px`;
      g.visible = box !== null;
      if (box) shown.push(box);
    }
    for (const b of bearings) {
      b.label.style.display = b.failed ? '' : 'none';
      if (!b.failed) continue;
      b.label.textContent = `failed (${(100 * (b.strain ? b.strain[frame] : 0)).toFixed(0)}%)`;
      const s = toScreen(b.mid);
      b.label.style.left = `${s.x}px`;
      b.label.style.top = `${s.y}px`;
    }
  }

  function resize() {
    const w = Math.max(host.clientWidth, 50);
    const h = Math.max(host.clientHeight, 50);
    renderer.setSize(w, h);
    camera.aspect = w / h;
    camera.updateProjectionMatrix();
  }
  const render = () => { renderer.render(scene, camera); placeLabels(); };
  controls.addEventListener('change', render);
  /** The joint whose label point is nearest to a pointer event, within kHoverRadius (else null). */
  const jointAt = (ev) => {
    const r = renderer.domElement.getBoundingClientRect();
    let best = null;
    let bestD = kHoverRadius;
    for (const g of gaps) {
      const dd = Math.hypot(g.x - (ev.clientX - r.left), g.y - (ev.clientY - r.top));
      if (g.onScreen && dd < bestD) { bestD = dd; best = g; }
    }
    return best;
  };
  renderer.domElement.addEventListener('pointermove', (ev) => {
    const g = jointAt(ev);
    if (g !== hovered) { hovered = g; placeLabels(); }
  });
  renderer.domElement.addEventListener('pointerleave', () => { if (hovered) { hovered = null; placeLabels(); } });
  renderer.domElement.addEventListener('click', (ev) => {
    const g = jointAt(ev);
    if (!g) return;
    if (pinned.has(g)) pinned.delete(g); else pinned.add(g);
    placeLabels();
  });

  // ---- views ------------------------------------------------------------------------------
  let view = '3d';
  // Points the first views must show: the box's corners and the ground motion's line.
  const fitPoints = [];
  for (let k = 0; k < 8; ++k)
    fitPoints.push(new THREE.Vector3(k & 1 ? box.max.x : box.min.x, k & 2 ? box.max.y : box.min.y, k & 4 ? box.max.z : box.min.z));
  if (data.ground.length) {
    const axis = new THREE.Vector3(...groundAxis).multiplyScalar(kGroundArrowRatio * size);
    fitPoints.push(groundOrigin.clone().sub(axis), groundOrigin.clone().add(axis));
  }
  /** Extent of the fit points on the screen (normalized device coordinates, -1..1), null if one is behind the camera. */
  const screenExtent = (points = fitPoints) => {
    camera.updateMatrixWorld();
    const e = { minX: Infinity, maxX: -Infinity, minY: Infinity, maxY: -Infinity };
    for (const p of points) {
      vec.copy(p).applyMatrix4(camera.matrixWorldInverse);
      if (vec.z >= -camera.near) return null;
      vec.applyMatrix4(camera.projectionMatrix);
      e.minX = Math.min(e.minX, vec.x); e.maxX = Math.max(e.maxX, vec.x);
      e.minY = Math.min(e.minY, vec.y); e.maxY = Math.max(e.maxY, vec.y);
    }
    return e;
  };
  /** Moves the camera along its line of sight and sideways until the fit points fill kFitMargin of
   *  the canvas's width or height, centred; kept as placed when the model's box already fits (so
   *  short bridges keep their first views). */
  function fitCamera() {
    const e0 = screenExtent(fitPoints.slice(0, 8));
    if (e0 && Math.max(-e0.minX, e0.maxX, -e0.minY, e0.maxY) <= kFitMargin) return;
    const dir = camera.position.clone().sub(controls.target).normalize();
    let d = camera.position.distanceTo(controls.target);
    const tanHalf = Math.tan((camera.fov * Math.PI) / 360);
    const right = new THREE.Vector3();
    const upv = new THREE.Vector3();
    for (let iter = 0; iter < 40; ++iter) {
      camera.position.copy(controls.target).addScaledVector(dir, d);
      camera.lookAt(controls.target);
      const e = screenExtent();
      if (!e) { d *= 2; continue; }
      const ratio = Math.max((e.maxX - e.minX) / 2, (e.maxY - e.minY) / 2) / kFitMargin;
      const mx = (e.minX + e.maxX) / 2;
      const my = (e.minY + e.maxY) / 2;
      if (Math.abs(ratio - 1) < 1e-3 && Math.abs(mx) < 1e-3 && Math.abs(my) < 1e-3) break;
      right.setFromMatrixColumn(camera.matrixWorld, 0);
      upv.setFromMatrixColumn(camera.matrixWorld, 1);
      const hh = d * tanHalf;
      controls.target.addScaledVector(right, 0.7 * mx * hh * camera.aspect).addScaledVector(upv, 0.7 * my * hh);
      d *= Math.min(Math.max(ratio, 0.5), 2);
    }
    camera.position.copy(controls.target).addScaledVector(dir, d);
  }
  function setView(name) {
    view = name;
    // distance at which the model's extent fills the view (perspective camera, vertical fov)
    const extent = box.getSize(new THREE.Vector3());
    const fit = (w, h) => 0.6 * Math.max(h, w / Math.max(camera.aspect, 1e-3)) / Math.tan((camera.fov * Math.PI) / 360);
    controls.target.copy(center);
    if (!zUp) {
      camera.up.set(0, 1, 0);
      camera.position.copy(center).add(new THREE.Vector3(0, 0, fit(extent.x, extent.y) + extent.z));
    } else if (name === 'plan') {
      camera.up.set(0, 1, 0);
      camera.position.copy(center).add(new THREE.Vector3(0, 0, fit(extent.x, extent.y) + extent.z));
    } else if (name === 'elevation') {
      camera.up.set(0, 0, 1);
      camera.position.copy(center).add(new THREE.Vector3(0, -fit(extent.x, extent.z) - extent.y, 0));
    } else if (name === 'joint' && gaps.length) {
      // close to the joint with the largest contact force now (the first joint when none is closed),
      // from the side at the height of the bearings
      const jointForce = (j) => j.contacts.reduce((sum, c) => sum + (c.force ? Math.max(c.force[frame], 0) : 0), 0);
      const g = gaps.reduce((best, j) => (jointForce(j) > jointForce(best) ? j : best), gaps[0]);
      tmpA.fromArray(position, 3 * g.ia).add(tmpB.fromArray(position, 3 * g.ib)).multiplyScalar(0.5);
      controls.target.copy(tmpA);
      camera.up.set(0, 0, 1);
      const d = Math.max(0.2 * size, 1e-3);
      camera.position.copy(tmpA).add(new THREE.Vector3(0.3 * d, -0.9 * d, -0.05 * d));
    } else {
      camera.up.set(0, 0, 1);
      const d = 1.15 * fit(Math.hypot(extent.x, extent.y), extent.z);
      camera.position.copy(center).add(new THREE.Vector3(0.35 * d, -0.85 * d, 0.4 * d));
    }
    camera.lookAt(controls.target);
    if (name !== 'joint') fitCamera();
    camera.lookAt(controls.target);
    controls.update();
    // plan and elevation: dragging scrolls along the bridge and the wheel zooms at the pointer
    const flat = name === 'plan' || name === 'elevation';
    controls.mouseButtons.LEFT = flat ? THREE.MOUSE.PAN : THREE.MOUSE.ROTATE;
    controls.zoomToCursor = flat;
    // in plan the girders are see-through, so the bearings under them show
    memberMaterial.opacity = name === 'plan' ? 0.35 : 1;
    blockMaterial.opacity = name === 'plan' ? 0.5 : 1;
    memberMaterial.depthWrite = blockMaterial.depthWrite = name !== 'plan';
    document.querySelectorAll('#views button').forEach((b) => b.classList.toggle('on', b.dataset.view === name));
    render();
  }
  document.querySelectorAll('#views button').forEach((b) => b.addEventListener('click', () => setView(b.dataset.view)));
  if (!gaps.length) document.querySelector('#views button[data-view="joint"]').style.display = 'none';

  // ---- plots ------------------------------------------------------------------------------
  const plotsHost = document.getElementById('plots');
  const times = Array.from(data.time);
  const cursorPlugin = {
    hooks: {
      draw: (u) => {
        if (data.frames === 0) return;
        const x = u.valToPos(data.time[frame], 'x', true);
        const ctx = u.ctx;
        ctx.save();
        ctx.strokeStyle = '#d62728';
        ctx.lineWidth = 2 * (window.devicePixelRatio || 1);
        ctx.beginPath();
        ctx.moveTo(x, u.bbox.top);
        ctx.lineTo(x, u.bbox.top + u.bbox.height);
        ctx.stroke();
        ctx.restore();
      },
    },
  };
  const plotSpecs = data.plots.map((p) => ({ label: p.label, source: p.source, values: p.values }));
  if (data.ground.length) {
    const along = new Float64Array(data.frames);
    for (let f = 0; f < data.frames; ++f) {
      const a = groundVector(f);
      along[f] = a[0] * groundAxis[0] + a[1] * groundAxis[1] + a[2] * groundAxis[2];
    }
    plotSpecs.push({ label: 'ground acceleration along the motion (m/s²)', source: 'UniformExcitation patterns', values: along });
  }
  const plots = plotSpecs.map((p) => {
    const el = document.createElement('div');
    el.className = 'plot';
    const head = document.createElement('div');
    head.style.padding = '2px 6px';
    el.appendChild(head);
    plotsHost.appendChild(el);
    const width = Math.max(plotsHost.clientWidth - 16, 280);
    const u = new uPlot({
      width, height: 150, title: '', plugins: [cursorPlugin], legend: { show: false },
      scales: { x: { time: false } },
      series: [{ label: 'time' }, { label: p.label, stroke: '#1f4e9c', width: 1.5 }],
      axes: [{ label: 'time (s)' }, { size: 70 }],
    }, [times, Array.from(p.values)], el);
    return { label: p.label, source: p.source, head, u, values: p.values };
  });
  function updatePlots() {
    for (const p of plots) {
      const v = data.frames ? p.values[frame] : NaN;
      p.head.textContent = `${p.label} = ${Number(v.toPrecision(5))}  (${p.source})`;
      p.u.redraw(false, false);
    }
  }

  // ---- controls -----------------------------------------------------------------------------
  const slider = document.getElementById('slider');
  const status = document.getElementById('status');
  const magInput = document.getElementById('mag');
  const playButton = document.getElementById('play');
  const speed = document.getElementById('speed');
  const nodesBox = document.getElementById('nodes');
  slider.max = String(Math.max(data.frames - 1, 0));
  magInput.value = String(magnification);
  nodesBox.addEventListener('change', () => { points.visible = nodesBox.checked; render(); });

  function setFrame(f) {
    frame = Math.min(Math.max(Math.round(f), 0), Math.max(data.frames - 1, 0));
    slider.value = String(frame);
    const t = data.frames ? data.time[frame] : 0;
    status.textContent = `t = ${t.toFixed(3)} s   frame ${frame + 1} / ${data.frames}`;
    place();
    updatePlots();
    render();
  }
  slider.addEventListener('input', () => { stop(); setFrame(Number(slider.value)); });
  magInput.addEventListener('input', () => {
    const m = Number(magInput.value);
    if (isFinite(m) && m >= 0) { magnification = m; setFrame(frame); }
  });

  let playing = false;
  let clockStart = 0;
  let timeStart = 0;
  function frameAtTime(t) {
    let lo = 0;
    let hi = data.frames - 1;
    while (lo < hi) {
      const mid = (lo + hi + 1) >> 1;
      if (data.time[mid] <= t) lo = mid; else hi = mid - 1;
    }
    return lo;
  }
  function tick(now) {
    if (!playing) return;
    const t = timeStart + ((now - clockStart) / 1000) * Number(speed.value);
    if (data.frames === 0 || t >= data.time[data.frames - 1]) { setFrame(data.frames - 1); stop(); return; }
    setFrame(frameAtTime(t));
    requestAnimationFrame(tick);
  }
  function stop() { playing = false; playButton.textContent = 'Play'; }
  playButton.addEventListener('click', () => {
    if (playing) { stop(); return; }
    if (data.frames < 2) return;
    if (frame >= data.frames - 1) setFrame(0);
    playing = true;
    playButton.textContent = 'Pause';
    clockStart = performance.now();
    timeStart = data.time[frame];
    requestAnimationFrame(tick);
  });
  speed.addEventListener('change', () => { if (playing) { clockStart = performance.now(); timeStart = data.time[frame]; } });
  window.addEventListener('resize', () => { resize(); render(); });

  resize();
  place();
  setView('3d');
  setFrame(0);

  // ---- test hook: what the browser test reads ----------------------------------------------
  const contactForceTotal = (f) => contacts.reduce((s, c) => s + (c.force ? Math.max(c.force[f], 0) : 0), 0);
  window.dabsViewer = {
    ready: true,
    /** Milliseconds from navigation start until the first frame was drawn. */
    readyMs: performance.now(),
    frames: data.frames,
    time: (f) => data.time[f],
    frame: () => frame,
    setFrame,
    setView,
    view: () => view,
    magnification: () => magnification,
    setMagnification: (m) => { magnification = m; magInput.value = String(m); setFrame(frame); },
    showNodes: (on) => { nodesBox.checked = on; points.visible = on; render(); },
    nodesShown: () => points.visible,
    nodeTags: () => data.nodes.slice(),
    coords: (tag) => data.coords[data.nodeIndex.get(tag)].slice(),
    displacement: (tag, f) => data.disp[data.nodeIndex.get(tag)].map((c) => c[f]),
    /** Position at which the node is drawn now (model coordinates). */
    drawnPosition: (tag) => Array.from(position.subarray(3 * data.nodeIndex.get(tag), 3 * data.nodeIndex.get(tag) + 3)),
    /** CSS pixel position in the page of a model point [x, y, z]. */
    project: (p) => {
      const s = toScreen(new THREE.Vector3(p[0], p[1], p[2]));
      const r = renderer.domElement.getBoundingClientRect();
      return { x: s.x + r.left, y: s.y + r.top };
    },
    canvasRect: () => { const r = renderer.domElement.getBoundingClientRect(); return { x: r.left, y: r.top, width: r.width, height: r.height }; },
    nodeColor: hex(kColors.node),
    background: hex(kColors.background),
    contactOpenColor: hex(kColors.contactOpen),
    contactClosedColor: hex(kColors.contactClosed),
    /** Whether the face of contact `tag` is lit now (null: no such contact). */
    contactClosed: (tag) => { const c = contacts.find((x) => x.tag === tag); return c ? c.face.closed : null; },
    /** Colour of the face of contact `tag` as drawn now. */
    contactFaceColor: (tag) => { const c = contacts.find((x) => x.tag === tag); return c ? '#' + c.face.mesh.material.color.getHexString() : null; },
    /** Centre of the face of contact `tag` as drawn now (model coordinates). */
    contactFaceCenter: (tag) => {
      const c = contacts.find((x) => x.tag === tag);
      if (!c) return null;
      const s = [0, 0, 0];
      for (const i of c.face.idx) for (let k = 0; k < 3; ++k) s[k] += position[3 * i + k] / c.face.idx.length;
      return s;
    },
    bearingColor: (tag) => { const b = bearings.find((x) => x.tag === tag); return b ? '#' + b.mesh.material.color.getHexString() : null; },
    bearingFailedMark: (tag) => { const b = bearings.find((x) => x.tag === tag); return b ? b.edges.visible && b.label.style.display !== 'none' : null; },
    bearingCenter: (tag) => { const b = bearings.find((x) => x.tag === tag); return b ? [b.mid.x, b.mid.y, b.mid.z] : null; },
    gapTexts: () => gaps.map((g) => g.el.textContent),
    /** Labels of the joints shown now: { label, left, top, right, bottom } in CSS px of the page. */
    visibleLabels: () => gaps.filter((g) => g.el.style.display !== 'none').map((g) => {
      const r = g.el.getBoundingClientRect();
      return { label: g.label, left: r.left, top: r.top, right: r.right, bottom: r.bottom };
    }),
    /** Extent on the page (CSS px) of everything drawn of the model: nodes, members, pads, faces. */
    modelExtent: () => {
      const e = { left: Infinity, top: Infinity, right: -Infinity, bottom: -Infinity };
      const r = renderer.domElement.getBoundingClientRect();
      const add = (arr) => {
        for (let k = 0; k + 2 < arr.length; k += 3) {
          const s = toScreen(new THREE.Vector3(arr[k], arr[k + 1], arr[k + 2]));
          e.left = Math.min(e.left, s.x + r.left); e.right = Math.max(e.right, s.x + r.left);
          e.top = Math.min(e.top, s.y + r.top); e.bottom = Math.max(e.bottom, s.y + r.top);
        }
      };
      add(position);
      for (const m of solids) add(m.geometry.attributes.position.array);
      for (const b of bearings) add(b.geometry.attributes.position.array);
      for (const f of faceList) add(f.geometry.attributes.position.array);
      for (const b of blocks) {
        b.mesh.updateMatrixWorld();
        const bb = new THREE.Box3().setFromObject(b.mesh);
        for (let k = 0; k < 8; ++k)
          add([k & 1 ? bb.max.x : bb.min.x, k & 2 ? bb.max.y : bb.min.y, k & 4 ? bb.max.z : bb.min.z]);
      }
      return e;
    },
    /** Shows the label of the joint nearest to a page point, as the pointer does (x, y CSS px). */
    hoverAt: (x, y) => {
      renderer.domElement.dispatchEvent(new PointerEvent('pointermove', { clientX: x, clientY: y, bubbles: true }));
    },
    /** Page position (CSS px) of joint k's label point. */
    jointPoint: (k) => { const r = renderer.domElement.getBoundingClientRect(); return { x: gaps[k].x + r.left, y: gaps[k].y + r.top }; },
    groundText: () => groundLabel.textContent,
    groundAcceleration: (f) => groundVector(f),
    memberCount: () => solids.length,
    /** Section outline [y0, z0, ..] of member `tag` (null: not drawn as a solid). */
    memberOutline: (tag) => { const m = solids.find((x) => x.tag === tag); return m ? m.outline.slice() : null; },
    /** Sum of the contacts' normal forces at frame f, and the frame where it is largest. */
    contactForceTotal,
    frameOfMaxContactForce: () => {
      let best = 0;
      for (let f = 1; f < data.frames; ++f) if (contactForceTotal(f) > contactForceTotal(best)) best = f;
      return best;
    },
    /** The uPlot instance of plot k (the browser test reads its scales). */
    plotAt: (k) => plots[k].u,
    plots: () => plots.map((p) => ({ label: p.label, source: p.source, values: Array.from(p.values), text: p.head.textContent })),
  };
}

try {
  main();
} catch (err) {
  const msg = document.createElement('pre');
  msg.style.cssText = 'color:#b00;padding:1em;white-space:pre-wrap';
  msg.textContent = 'DABS viewer failed: ' + (err && err.stack ? err.stack : err);
  document.body.prepend(msg);
  window.dabsViewer = { ready: false, error: String(err) };
}
