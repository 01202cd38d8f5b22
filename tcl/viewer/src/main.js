// SPDX-License-Identifier: MIT
// The DABS post-processor page: the deformed model in a three.js scene, a time slider, play/pause,
// a magnification control, and uPlot time histories with a cursor at the current time.
import * as THREE from 'three';
import { OrbitControls } from 'three/examples/jsm/controls/OrbitControls.js';
import uPlot from 'uplot';
import 'uplot/dist/uPlot.min.css';
import { readData } from './data.js';

const kColors = {
  background: 0xffffff,
  node: 0x00b050,
  beam: 0x1f4e9c,
  link: 0x7f7f7f,
  bearing: 0xe08a1e,
  bearingDesign: 0xf0c020,   // damage 1: past the design shear strain
  bearingFailed: 0xd62728,   // damage 2: failed
  contactOpen: 0xb0b0b0,
  contactClosed: 0xff00aa,
};
const kNodePointSize = 7;     // px
const kBearingSizeRatio = 0.025;  // bearing box edge / model size
const kTargetDeformationRatio = 0.1;  // auto magnification: peak drawn displacement / model size

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
  let magnification = peak > 0 ? niceNumber((kTargetDeformationRatio * size) / peak) : 1;

  const scene = new THREE.Scene();
  scene.background = new THREE.Color(kColors.background);
  scene.add(new THREE.AmbientLight(0xffffff, 0.7));
  const sun = new THREE.DirectionalLight(0xffffff, 1.6);
  scene.add(sun);
  const zUp = data.ndm === 3;
  const camera = new THREE.PerspectiveCamera(40, 1, size * 1e-3, size * 100);
  if (zUp) {
    camera.up.set(0, 0, 1);
    camera.position.copy(center).add(new THREE.Vector3(0.55, -1.35, 0.55).multiplyScalar(size));
    sun.position.set(1, -2, 3);
  } else {
    camera.position.copy(center).add(new THREE.Vector3(0, 0, 1.6 * size));
    sun.position.set(1, 2, 3);
  }
  camera.lookAt(center);

  const host = document.getElementById('scene');
  const renderer = new THREE.WebGLRenderer({ antialias: true, preserveDrawingBuffer: true });
  renderer.setPixelRatio(window.devicePixelRatio || 1);
  host.appendChild(renderer.domElement);
  const controls = new OrbitControls(camera, renderer.domElement);
  controls.target.copy(center);
  controls.update();

  // Elements by kind: beams and links as line segments; bearings as boxes; contacts as a line from
  // the contactor to the target centre plus a marker at the contactor.
  const segments = { beam: [], link: [] };
  const bearings = [];
  const contacts = [];
  const statusOf = new Map(data.contacts.map((c) => [c.tag, c.status]));
  const damageOf = new Map(data.bearings.map((b) => [b.tag, b.damage]));
  for (const e of data.elements) {
    const idx = e.nodes.map((t) => data.nodeIndex.get(t));
    if (idx.some((i) => i === undefined)) continue;
    if (e.kind === 'beam' || e.kind === 'link') {
      for (let k = 0; k + 1 < idx.length; ++k) segments[e.kind].push(idx[k], idx[k + 1]);
    } else if (e.kind === 'bearing') {
      bearings.push({ tag: e.tag, idx, damage: damageOf.get(e.tag) });
    } else if (e.kind === 'contact') {
      contacts.push({ tag: e.tag, idx, status: statusOf.get(e.tag) });
    }
  }
  const position = new Float32Array(3 * nNodes);  // drawn node positions
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
  const bearingSize = kBearingSizeRatio * size;
  const bearingGeometry = new THREE.BoxGeometry(1, 1, 1);
  for (const b of bearings) {
    b.mesh = new THREE.Mesh(bearingGeometry, new THREE.MeshLambertMaterial({ color: kColors.bearing }));
    scene.add(b.mesh);
  }
  const contactLineGeometry = new THREE.BufferGeometry();
  contactLineGeometry.setAttribute('position', new THREE.BufferAttribute(new Float32Array(6 * contacts.length), 3));
  contactLineGeometry.setAttribute('color', new THREE.BufferAttribute(new Float32Array(6 * contacts.length), 3));
  const contactLines = new THREE.LineSegments(contactLineGeometry, new THREE.LineBasicMaterial({ vertexColors: true }));
  contactLines.frustumCulled = false;
  scene.add(contactLines);
  const contactMarkerGeometry = new THREE.SphereGeometry(0.6 * bearingSize, 16, 12);
  for (const c of contacts) {
    c.mesh = new THREE.Mesh(contactMarkerGeometry, new THREE.MeshLambertMaterial({ color: kColors.contactClosed }));
    scene.add(c.mesh);
  }
  const pointGeometry = new THREE.BufferGeometry();
  pointGeometry.setAttribute('position', new THREE.BufferAttribute(position, 3));
  const points = new THREE.Points(pointGeometry, new THREE.PointsMaterial({
    color: kColors.node, size: kNodePointSize, sizeAttenuation: false, depthTest: false }));
  points.renderOrder = 10;
  points.frustumCulled = false;
  scene.add(points);

  // ---- legend ---------------------------------------------------------------------------
  const legend = document.getElementById('legend');
  const legendRows = [['node', kColors.node], ['girder / pier', kColors.beam]];
  if (segments.link.length) legendRows.push(['link', kColors.link]);
  if (bearings.length) legendRows.push(['bearing', kColors.bearing], ['bearing past design strain', kColors.bearingDesign], ['bearing failed', kColors.bearingFailed]);
  if (contacts.length) legendRows.push(['contact open', kColors.contactOpen], ['contact closed', kColors.contactClosed]);
  legend.innerHTML = legendRows.map(([name, c]) => `<div><span style="background:${hex(c)}"></span>${name}</div>`).join('');

  // ---- state and drawing --------------------------------------------------------------------
  let frame = 0;
  const drawn = (i, f) => {
    const c = data.coords[i];
    const d = data.disp[i];
    return [c[0] + magnification * d[0][f], c[1] + magnification * d[1][f], c[2] + magnification * d[2][f]];
  };
  const yAxis = new THREE.Vector3(0, 1, 0);
  const zAxis = new THREE.Vector3(0, 0, 1);
  const tmpA = new THREE.Vector3();
  const tmpB = new THREE.Vector3();
  function place() {
    for (let i = 0; i < nNodes; ++i) position.set(drawn(i, frame), 3 * i);
    pointGeometry.attributes.position.needsUpdate = true;
    for (const set of lineSets) {
      const a = set.geometry.attributes.position.array;
      set.pairs.forEach((i, k) => a.set(position.subarray(3 * i, 3 * i + 3), 3 * k));
      set.geometry.attributes.position.needsUpdate = true;
    }
    for (const b of bearings) {
      tmpA.fromArray(position, 3 * b.idx[0]);
      tmpB.fromArray(position, 3 * b.idx[b.idx.length - 1]);
      b.mesh.position.copy(tmpA).add(tmpB).multiplyScalar(0.5);
      // The box spans the bearing's two nodes (its axis along their connecting line, so shear
      // deformation tilts it); coincident nodes give a flat box.
      const length = tmpA.distanceTo(tmpB);
      b.mesh.scale.set(bearingSize, Math.max(length, 0.5 * bearingSize), bearingSize);
      if (length > 1e-9 * size) b.mesh.quaternion.setFromUnitVectors(yAxis, tmpB.sub(tmpA).normalize());
      else b.mesh.quaternion.setFromUnitVectors(yAxis, zUp ? zAxis : yAxis);
      const dmg = b.damage ? b.damage[frame] : 0;
      b.mesh.material.color.setHex(dmg >= 2 ? kColors.bearingFailed : dmg >= 1 ? kColors.bearingDesign : kColors.bearing);
    }
    const cp = contactLineGeometry.attributes.position.array;
    const cc = contactLineGeometry.attributes.color.array;
    const open = new THREE.Color(kColors.contactOpen);
    const closed = new THREE.Color(kColors.contactClosed);
    contacts.forEach((c, k) => {
      tmpA.fromArray(position, 3 * c.idx[0]);
      tmpB.set(0, 0, 0);
      for (let j = 1; j < c.idx.length; ++j) tmpB.add(new THREE.Vector3().fromArray(position, 3 * c.idx[j]));
      if (c.idx.length > 1) tmpB.multiplyScalar(1 / (c.idx.length - 1));
      tmpA.toArray(cp, 6 * k);
      tmpB.toArray(cp, 6 * k + 3);
      const isClosed = c.status && c.status[frame] > 0;
      const col = isClosed ? closed : open;
      col.toArray(cc, 6 * k);
      col.toArray(cc, 6 * k + 3);
      c.mesh.position.copy(tmpA);
      c.mesh.visible = isClosed;
    });
    contactLineGeometry.attributes.position.needsUpdate = true;
    contactLineGeometry.attributes.color.needsUpdate = true;
  }

  function resize() {
    const w = Math.max(host.clientWidth, 50);
    const h = Math.max(host.clientHeight, 50);
    renderer.setSize(w, h);
    camera.aspect = w / h;
    camera.updateProjectionMatrix();
  }
  const render = () => renderer.render(scene, camera);
  controls.addEventListener('change', render);

  // ---- plots ----------------------------------------------------------------------------
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
  const plots = data.plots.map((p) => {
    const box = document.createElement('div');
    box.className = 'plot';
    const head = document.createElement('div');
    head.style.padding = '2px 6px';
    box.appendChild(head);
    plotsHost.appendChild(box);
    const width = Math.max(plotsHost.clientWidth - 16, 280);
    const u = new uPlot({
      width, height: 170, title: '', plugins: [cursorPlugin], legend: { show: false },
      scales: { x: { time: false } },
      series: [{ label: 'time' }, { label: p.label, stroke: '#1f4e9c', width: 1.5 }],
      axes: [{ label: 'time' }, { size: 70 }],
    }, [times, Array.from(p.values)], box);
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
  slider.max = String(Math.max(data.frames - 1, 0));
  magInput.value = String(magnification);

  function setFrame(f) {
    frame = Math.min(Math.max(Math.round(f), 0), Math.max(data.frames - 1, 0));
    slider.value = String(frame);
    const t = data.frames ? data.time[frame] : 0;
    status.textContent = `t = ${t.toPrecision(5)} s   frame ${frame + 1} / ${data.frames}`;
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
  setFrame(0);

  // ---- test hook: what the browser test reads ----------------------------------------------
  const vec = new THREE.Vector3();
  window.dabsViewer = {
    ready: true,
    /** Milliseconds from navigation start until the first frame was drawn. */
    readyMs: performance.now(),
    frames: data.frames,
    time: (f) => data.time[f],
    frame: () => frame,
    setFrame,
    magnification: () => magnification,
    nodeTags: () => data.nodes.slice(),
    coords: (tag) => data.coords[data.nodeIndex.get(tag)].slice(),
    displacement: (tag, f) => data.disp[data.nodeIndex.get(tag)].map((c) => c[f]),
    /** Position at which the node is drawn now (model coordinates). */
    drawnPosition: (tag) => Array.from(position.subarray(3 * data.nodeIndex.get(tag), 3 * data.nodeIndex.get(tag) + 3)),
    /** CSS pixel position in the canvas of a model point [x, y, z]. */
    project: (p) => {
      vec.set(p[0], p[1], p[2]).project(camera);
      const r = renderer.domElement.getBoundingClientRect();
      return { x: (vec.x + 1) / 2 * r.width + r.left, y: (1 - vec.y) / 2 * r.height + r.top };
    },
    canvasRect: () => { const r = renderer.domElement.getBoundingClientRect(); return { x: r.left, y: r.top, width: r.width, height: r.height }; },
    nodeColor: hex(kColors.node),
    background: hex(kColors.background),
    contactClosed: (tag) => { const c = contacts.find((x) => x.tag === tag); return c ? c.mesh.visible : null; },
    bearingColor: (tag) => { const b = bearings.find((x) => x.tag === tag); return b ? '#' + b.mesh.material.color.getHexString() : null; },
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
