// SPDX-License-Identifier: MIT
// Browser test of the Viewer page: a small analysis (bridge.tcl, run by dabs) writes the page plus
// Node and Element recorder files; headless Chromium (Debian's), driven by playwright-core, opens
// the page from disk and checks that
//   - the canvas draws the model (pixels other than the background), members as solids,
//   - node markers are off by default; shown, they sit at coordinates + magnification x the
//     displacement in the Node recorder's file, for every node, as the slider moves,
//   - a contact face changes colour exactly when the Element recorder's gap closes (the colour is
//     also read from the canvas pixels),
//   - a bearing's colour follows its recorded shear strain on the strain scale, and the failed mark
//     its recorded damage,
//   - the gap printed at the joint is the recorded relative displacement, the ground acceleration
//     the closed form of the test's Trig series,
//   - the plan and elevation views look along Z and Y,
//   - the plots hold the recorded values, draw them, and every plot's time cursor follows the slider,
//   - the screenshots (screenshot.mjs) are taken at the frame of the largest recorded contact force,
//   - on viaducts of 10 and 100 spans (viaduct.tcl), the first view and the plan and elevation
//     views show the whole model inside the canvas, the joint labels shown never overlap (their
//     boxes as laid out by the browser), and a hidden joint's label shows on hover,
// and saves screenshots in DABS_VIEWER_OUT.
// Environment: DABS_EXE (the dabs program), DABS_VIEWER_MODULES (node_modules with
// playwright-core), DABS_VIEWER_OUT (output folder). Run by ctest as `node --test`.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { createRequire } from 'node:module';
import { execFileSync } from 'node:child_process';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { strainColor } from '../src/colors.js';
import { screenshots } from './screenshot.mjs';

const here = path.dirname(fileURLToPath(import.meta.url));
const out = process.env.DABS_VIEWER_OUT || fs.mkdtempSync(path.join(os.tmpdir(), 'dabs-viewer-'));
const require = createRequire(path.join(process.env.DABS_VIEWER_MODULES || '', 'x.js'));
const { chromium } = require('playwright-core');

// Quantization of the page's data: every value is within half of peak / 1e5 of the recorded one
// (ViewerRecorder::kQuantizationLevels); drawn positions are float32 (7 digits).
const kLevels = 1e5;
const kFloat32 = 1e-6;
const kNodeColor = [0x00, 0xb0, 0x50];
const kColorTolerance = 40;  // per channel, for antialiased edges

function readRows(file) {
  return fs.readFileSync(file, 'utf8').trim().split('\n').map((l) => l.trim().split(/\s+/).map(Number));
}
const peakOf = (values) => values.reduce((m, v) => Math.max(m, Math.abs(v)), 0);

let context;
let page;
let profile;
let disp;   // rows: time, then x y z per node of `nodes`
let gap;    // rows: time, gap
let force;  // rows: time, N, t1, t2 of the contact
let strain; // rows: time, shear strain of bearing 21
let damage; // rows: time, damage of bearing 21
const nodes = [1, 2, 3, 4, 11, 12, 13, 41, 42, 43, 44];

// The analysis runs first; until `recorder` dispatches the Viewer type (tcl/commands/
// RecorderCommands.cpp), the whole test is reported as skipped rather than failed.
fs.mkdirSync(out, { recursive: true });
let notDispatched = false;
try {
  execFileSync(process.env.DABS_EXE, [path.join(here, 'bridge.tcl'), out], { stdio: 'pipe' });
} catch (e) {
  const text = String(e.stdout) + String(e.stderr);
  if (!/recorder Viewer/.test(text) || !/expected Node, EnvelopeNode/.test(text)) throw e;
  notDispatched = true;
}
const skip = notDispatched ? 'recorder Viewer is not dispatched by `recorder` yet' : false;

before(async () => {
  if (skip) return;
  disp = readRows(path.join(out, 'disp.out'));
  gap = readRows(path.join(out, 'gap.out'));
  force = readRows(path.join(out, 'force.out'));
  strain = readRows(path.join(out, 'strain.out'));
  damage = readRows(path.join(out, 'damage.out'));
  profile = fs.mkdtempSync(path.join(os.tmpdir(), 'dabs-viewer-chromium-'));
  context = await chromium.launchPersistentContext(profile, {
    executablePath: '/usr/bin/chromium',
    headless: true,
    viewport: { width: 1400, height: 800 },
    args: ['--headless', '--no-sandbox', '--disable-gpu', '--disable-quic', '--no-first-run',
      '--disable-background-networking', '--disable-component-update', '--disable-sync'],
  });
  page = await context.newPage();
  const errors = [];
  page.on('pageerror', (e) => errors.push(e.message));
  // Nothing may be fetched: the page is self-contained.
  const requests = [];
  page.on('request', (r) => { if (!r.url().startsWith('file:') && !r.url().startsWith('data:')) requests.push(r.url()); });
  await page.goto('file://' + path.join(out, 'bridge.html'));
  await page.waitForFunction(() => window.dabsViewer !== undefined, null, { timeout: 30000 });
  const ready = await page.evaluate(() => window.dabsViewer.ready);
  assert.equal(ready, true, 'viewer failed: ' + (await page.evaluate(() => window.dabsViewer.error)) + errors.join('; '));
  assert.deepEqual(requests, [], 'the page fetched nothing');
});

after(async () => {
  if (context) await context.close();
  if (profile) fs.rmSync(profile, { recursive: true, force: true });  // the browser's own files
});

/** Pixels of a canvas (CSS selector) that differ from white; and the RGB at CSS points. */
async function canvasStats(selector, points = []) {
  return page.evaluate(([sel, pts]) => {
    const c = document.querySelector(sel);
    const copy = document.createElement('canvas');
    copy.width = c.width;
    copy.height = c.height;
    const g = copy.getContext('2d');
    g.drawImage(c, 0, 0);
    const img = g.getImageData(0, 0, c.width, c.height).data;
    let count = 0;
    for (let i = 0; i < img.length; i += 4)
      if (Math.abs(img[i] - 255) + Math.abs(img[i + 1] - 255) + Math.abs(img[i + 2] - 255) > 30) ++count;
    const r = c.getBoundingClientRect();
    const sx = c.width / r.width;
    const sy = c.height / r.height;
    // For each point: the pixels within 2 CSS px.
    const near = pts.map((p) => {
      const found = [];
      for (let dy = -2; dy <= 2; ++dy)
        for (let dx = -2; dx <= 2; ++dx) {
          const x = Math.round((p.x - r.left + dx) * sx);
          const y = Math.round((p.y - r.top + dy) * sy);
          if (x < 0 || y < 0 || x >= c.width || y >= c.height) continue;
          const k = 4 * (y * c.width + x);
          found.push([img[k], img[k + 1], img[k + 2]]);
        }
      return found;
    });
    return { count, total: c.width * c.height, near };
  }, [selector, points]);
}

async function moveSlider(frame) {
  await page.evaluate((f) => {
    const s = document.getElementById('slider');
    s.value = String(f);
    s.dispatchEvent(new Event('input', { bubbles: true }));
  }, frame);
  assert.equal(await page.evaluate(() => window.dabsViewer.frame()), frame);
}

test('the page has one frame per recorded step', { skip }, async () => {
  const frames = await page.evaluate(() => window.dabsViewer.frames);
  assert.equal(frames, disp.length);
  for (const f of [0, frames - 1])
    assert.ok(Math.abs((await page.evaluate((i) => window.dabsViewer.time(i), f)) - disp[f][0]) < 1e-9);
});

test('the canvas draws the model', { skip }, async () => {
  const s = await canvasStats('#scene canvas');
  assert.ok(s.count > 2000, `only ${s.count} non-background pixels of ${s.total}`);
});

test('node markers are off by default', { skip }, async () => {
  assert.equal(await page.evaluate(() => window.dabsViewer.nodesShown()), false);
  assert.equal(await page.evaluate(() => document.getElementById('nodes').checked), false);
});

test('members are drawn as solids of their sections', { skip }, async () => {
  // -beamSection gives the two girder elements and pier 1 a section, pier 2 has a fiber section
  assert.equal(await page.evaluate(() => window.dabsViewer.memberCount()), 4);
  // the fiber outline: the hull of the fibers scaled to the section's area, pi 0.6^2
  const o = await page.evaluate(() => window.dabsViewer.memberOutline(2));
  let area = 0;
  let rMax = 0;
  for (let k = 0; k < o.length; k += 2) {
    const j = (k + 2) % o.length;
    area += 0.5 * (o[k] * o[j + 1] - o[j] * o[k + 1]);
    rMax = Math.max(rMax, Math.hypot(o[k], o[k + 1]));
  }
  assert.ok(Math.abs(area - Math.PI * 0.36) <= 1e-4 * Math.PI * 0.36, `outline area ${area}`);
  assert.ok(Math.abs(rMax - 0.6) <= 0.05 * 0.6, `outline radius ${rMax}`);
});

test('moving the slider moves the drawn nodes to the recorded positions', { skip }, async () => {
  await page.evaluate(() => window.dabsViewer.showNodes(true));
  const mag = await page.evaluate(() => window.dabsViewer.magnification());
  assert.ok(mag > 0);
  // Frame where the girder end (node 13, column of x) moves most, and two others.
  const col13 = 1 + 3 * nodes.indexOf(13);
  let fMax = 0;
  disp.forEach((row, f) => { if (Math.abs(row[col13]) > Math.abs(disp[fMax][col13])) fMax = f; });
  const peaks = nodes.map((_, i) => [0, 1, 2].map((c) => peakOf(disp.map((r) => r[1 + 3 * i + c]))));
  const screen = {};
  for (const f of [0, Math.floor(disp.length / 2), fMax]) {
    await moveSlider(f);
    const expected = [];
    for (const [i, tag] of nodes.entries()) {
      const x0 = await page.evaluate((t) => window.dabsViewer.coords(t), tag);
      const drawn = await page.evaluate((t) => window.dabsViewer.drawnPosition(t), tag);
      const p = [0, 1, 2].map((c) => x0[c] + mag * disp[f][1 + 3 * i + c]);
      for (let c = 0; c < 3; ++c) {
        const tol = mag * (0.5 * peaks[i][c] / kLevels) + kFloat32 * (Math.abs(p[c]) + 1);
        assert.ok(Math.abs(drawn[c] - p[c]) <= tol,
          `frame ${f} node ${tag} component ${c}: drawn ${drawn[c]}, recorded ${p[c]} (tol ${tol})`);
      }
      expected.push(p);
    }
    // A node marker is drawn where the recorded position projects on the screen.
    const pts = [];
    for (const p of expected) pts.push(await page.evaluate((q) => window.dabsViewer.project(q), p));
    const s = await canvasStats('#scene canvas', pts);
    s.near.forEach((pixels, k) => {
      const hit = pixels.some((px) => px.every((v, c) => Math.abs(v - kNodeColor[c]) <= kColorTolerance));
      assert.ok(hit, `frame ${f}: no node marker at the recorded position of node ${nodes[k]}`);
    });
    screen[f] = pts[nodes.indexOf(13)];
  }
  const moved = Math.hypot(screen[fMax].x - screen[0].x, screen[fMax].y - screen[0].y);
  assert.ok(moved > 5, `node 13 moved only ${moved} px on the screen`);
  await moveSlider(fMax);
  await page.screenshot({ path: path.join(out, 'viewer.png') });
  await page.evaluate(() => window.dabsViewer.showNodes(false));
});

const rgb = (h) => [1, 3, 5].map((i) => parseInt(h.slice(i, i + 2), 16));

test('a contact face changes colour when the recorded contact closes', { skip }, async () => {
  const [openColor, closedColor] = await page.evaluate(() => [window.dabsViewer.contactOpenColor, window.dabsViewer.contactClosedColor]);
  assert.notEqual(openColor, closedColor);
  let closedFrames = 0;
  let openFrames = 0;
  let changes = 0;
  let previous = null;
  for (let f = 0; f < gap.length; ++f) {
    const g = gap[f][1];
    if (Math.abs(g) < 1e-9) continue;  // touching: either state
    await moveSlider(f);
    const color = await page.evaluate(() => window.dabsViewer.contactFaceColor(51));
    assert.equal(color, g < 0 ? closedColor : openColor, `frame ${f}: gap ${g}, face colour ${color}`);
    if (previous !== null && previous !== color) ++changes;
    previous = color;
    if (g < 0) ++closedFrames; else ++openFrames;
  }
  assert.ok(closedFrames > 0 && openFrames > 0 && changes >= 2, 'the test analysis closes and opens the contact');
  // what is on the screen: the face's pixels in the 3D view, open and closed
  const fClosed = gap.findIndex((r) => r[1] < -1e-3);
  const fOpen = gap.findIndex((r) => r[1] > 1e-3);
  for (const [f, want] of [[fClosed, closedColor], [fOpen, openColor]]) {
    await moveSlider(f);
    const c = await page.evaluate(() => window.dabsViewer.project(window.dabsViewer.contactFaceCenter(51)));
    const s = await canvasStats('#scene canvas', [c]);
    const target = rgb(want);
    const hit = s.near[0].some((px) => px.every((v, k) => Math.abs(v - target[k]) <= 60));
    assert.ok(hit, `frame ${f}: the face is not drawn in ${want} at its centre (pixels ${JSON.stringify(s.near[0].slice(0, 3))})`);
  }
});

test("a bearing's colour follows its recorded shear strain", { skip }, async () => {
  assert.equal(strain.length, gap.length);
  const peakStrain = peakOf(strain.map((r) => r[1]));
  const q = peakStrain / kLevels;
  const seen = new Set();
  for (let f = 0; f < strain.length; f += 7) {
    await moveSlider(f);
    const color = await page.evaluate(() => window.dabsViewer.bearingColor(21));
    // the strain drawn is the recorded one to half a quantization level: the colour lies between
    // the scale's colours at the two ends of that interval
    const s = Math.abs(strain[f][1]);
    const lo = rgb(strainColor(Math.max(s - q, 0)));
    const hi = rgb(strainColor(s + q));
    const got = rgb(color);
    got.forEach((v, k) => assert.ok(v >= Math.min(lo[k], hi[k]) - 1 && v <= Math.max(lo[k], hi[k]) + 1,
      `frame ${f}: strain ${s}, colour ${color}, scale ${strainColor(s)}`));
    seen.add(color);
    const failed = await page.evaluate(() => window.dabsViewer.bearingFailedMark(21));
    assert.equal(failed, damage[f][1] >= 2, `frame ${f}: damage ${damage[f][1]}, failed mark ${failed}`);
  }
  assert.ok(seen.size > 5, `only ${seen.size} colours over the strain history`);
  assert.ok(peakStrain > 3.0, 'the test bearing passes 300 %');
});

test('the joint gap and the ground acceleration are printed', { skip }, async () => {
  const f = 150;
  await moveSlider(f);
  const [text] = await page.evaluate(() => window.dabsViewer.gapTexts());
  const dx = disp[f][1 + 3 * nodes.indexOf(41)] - disp[f][1 + 3 * nodes.indexOf(13)];
  const m = /Joint: ([-+0-9.]+) m long\./.exec(text);
  assert.ok(m, text);
  assert.ok(Math.abs(Number(m[1]) - dx) <= 0.0006, `${text} vs recorded ${dx}`);
  assert.match(text, gap[f][1] > 0 ? /clear gap/ : /in contact/);
  // timeSeries Trig 1 0.0 3.0 1.0 -factor 3.0 along X: a_g = 3 sin(2 pi t)
  for (const k of [37, 150, 222]) {
    const a = await page.evaluate((i) => window.dabsViewer.groundAcceleration(i), k);
    const t = disp[k][0];
    assert.ok(Math.abs(a[0] - 3 * Math.sin(2 * Math.PI * t)) <= 3e-5 * 3 + 1e-9, `frame ${k}: ${a[0]}`);
    assert.equal(a[1], 0);
  }
  assert.match(await page.evaluate(() => window.dabsViewer.groundText()), /ground acceleration .* m\/s²/);
});

test('plan and elevation look along Z and along Y', { skip }, async () => {
  await moveSlider(0);
  for (const [view, same] of [['plan', 2], ['elevation', 1]]) {
    await page.evaluate((v) => window.dabsViewer.setView(v), view);
    // two points that differ only along the viewing axis fall on the same pixel
    const p = [10, 0, 8];
    const q = p.slice();
    q[same] += 5;
    const [a, b] = await page.evaluate(([x, y]) => [window.dabsViewer.project(x), window.dabsViewer.project(y)], [p, q]);
    const r = [15, 0, 8];  // and a point 5 m along X does not
    const c = await page.evaluate((x) => window.dabsViewer.project(x), r);
    assert.ok(Math.hypot(a.x - b.x, a.y - b.y) < 0.5 * Math.hypot(a.x - c.x, a.y - c.y), `${view}: ${JSON.stringify([a, b, c])}`);
  }
  await page.evaluate(() => window.dabsViewer.setView('3d'));
});

test('the plots show the recorded values', { skip }, async () => {
  const plots = await page.evaluate(() => window.dabsViewer.plots());
  assert.deepEqual(plots.map((p) => p.label), ['girder end x', 'contact gap', 'bearing 21 shear strain',
    'ground acceleration along the motion (m/s²)']);
  const recorded = [disp.map((r) => r[1 + 3 * nodes.indexOf(13)]), gap.map((r) => r[1])];
  for (let k = 0; k < 2; ++k) {
    const tol = 0.5 * peakOf(recorded[k]) / kLevels * (1 + 1e-9);
    assert.equal(plots[k].values.length, recorded[k].length);
    recorded[k].forEach((v, f) => assert.ok(Math.abs(plots[k].values[f] - v) <= tol,
      `${plots[k].label} frame ${f}: plotted ${plots[k].values[f]}, recorded ${v}`));
  }
  // Each plot draws its curve, and its heading shows the value at the slider's frame.
  const f = 123;
  await moveSlider(f);
  const heads = await page.evaluate(() => window.dabsViewer.plots().map((p) => p.text));
  const shown = Number(/= (\S+)/.exec(heads[1])[1]);
  assert.ok(Math.abs(shown - gap[f][1]) <= 1e-4 * peakOf(recorded[1]), `heading ${heads[1]} vs ${gap[f][1]}`);
  const n = await page.evaluate(() => document.querySelectorAll('.plot canvas').length);
  assert.equal(n, 4, 'three plots and the ground acceleration');
  for (let k = 1; k <= n; ++k) {
    const s = await canvasStats(`.plot:nth-of-type(${k}) canvas`);
    assert.ok(s.count > 500, `plot ${k} draws only ${s.count} pixels`);
  }
});

test("every plot's time cursor follows the slider", { skip }, async () => {
  const red = [0xd6, 0x27, 0x28];
  for (const f of [40, 250]) {
    await moveSlider(f);
    const n = await page.evaluate(() => document.querySelectorAll('.plot').length);
    for (let k = 0; k < n; ++k) {
      // the cursor's canvas column at the time of the frame, halfway up the plotting area
      const px = await page.evaluate(([i, t]) => {
        const el = document.querySelectorAll('.plot')[i];
        const c = el.querySelector('canvas');
        const u = window.dabsViewer.plotAt(i);
        const x = Math.round(u.valToPos(t, 'x', true));
        const y = Math.round(u.bbox.top + 0.5 * u.bbox.height);
        const copy = document.createElement('canvas');
        copy.width = c.width; copy.height = c.height;
        const g = copy.getContext('2d');
        g.drawImage(c, 0, 0);
        const row = [];
        for (let dx = -1; dx <= 1; ++dx) row.push(Array.from(g.getImageData(x + dx, y, 1, 1).data.slice(0, 3)));
        return row;
      }, [k, disp[f][0]]);
      const hit = px.some((p) => p.every((v, c) => Math.abs(v - red[c]) <= 40));
      assert.ok(hit, `frame ${f}, plot ${k}: no cursor at the frame's time (${JSON.stringify(px)})`);
    }
  }
});

test('screenshots are taken at the largest recorded contact force', { skip }, async () => {
  let fMax = 0;
  force.forEach((r, f) => { if (r[1] > force[fMax][1]) fMax = f; });
  const r = await screenshots(page, out, 'viewer-contact');
  assert.equal(r.frame, fMax);
  assert.ok(Math.abs(r.force - force[fMax][1]) <= 1e-4 * force[fMax][1], `${r.force} vs ${force[fMax][1]}`);
  assert.equal(r.files.length, 4);
  for (const file of r.files) assert.ok(fs.statSync(file).size > 10000, file);
});

// Long viaducts: the whole model in the canvas and no two joint labels overlapping.
async function openViaduct(spans) {
  execFileSync(process.env.DABS_EXE, [path.join(here, 'viaduct.tcl'), out, String(spans)], { stdio: 'pipe' });
  const p = await context.newPage();
  const errors = [];
  p.on('pageerror', (e) => errors.push(e.message));
  await p.goto('file://' + path.join(out, `viaduct${spans}.html`));
  await p.waitForFunction(() => window.dabsViewer !== undefined, null, { timeout: 30000 });
  assert.equal(await p.evaluate(() => window.dabsViewer.ready), true, errors.join('; '));
  return p;
}

const intersects = (a, b) => a.left < b.right && b.left < a.right && a.top < b.bottom && b.top < a.bottom;

/** The model's drawn extent lies in the canvas and the labels shown are disjoint and in the canvas. */
async function checkFitAndLabels(p, what) {
  const [c, e, labels] = await p.evaluate(() => [window.dabsViewer.canvasRect(), window.dabsViewer.modelExtent(),
    window.dabsViewer.visibleLabels()]);
  assert.ok(e.left >= c.x && e.right <= c.x + c.width && e.top >= c.y && e.bottom <= c.y + c.height,
    `${what}: model drawn over ${JSON.stringify(e)}, canvas ${JSON.stringify(c)}`);
  // and it fills a good part of the canvas's width (a long bridge lies along the screen)
  assert.ok(e.right - e.left >= 0.5 * c.width, `${what}: model only ${e.right - e.left} px wide of ${c.width}`);
  assert.ok(labels.length >= 1, `${what}: no joint label shown`);
  for (const l of labels)
    assert.ok(l.left >= c.x - 0.5 && l.right <= c.x + c.width + 0.5, `${what}: label ${l.label} outside the canvas`);
  for (let i = 0; i < labels.length; ++i)
    for (let j = i + 1; j < labels.length; ++j)
      assert.ok(!intersects(labels[i], labels[j]), `${what}: labels ${labels[i].label} and ${labels[j].label} overlap: ` +
        JSON.stringify([labels[i], labels[j]]));
  return labels;
}

for (const spans of [10, 100]) {
  test(`a viaduct of ${spans} spans fits the views and its joint labels do not overlap`, { skip }, async () => {
    const p = await openViaduct(spans);
    try {
      assert.equal(await p.evaluate(() => window.dabsViewer.gapTexts().length), spans - 1);
      const frames = await p.evaluate(() => window.dabsViewer.frames);
      // the first view as opened, then later frames (the labels shown follow the largest values)
      const first = await checkFitAndLabels(p, 'first view');
      assert.ok(first.length < spans - 1 || spans <= 10, 'not every label of a long viaduct fits');
      for (const f of [Math.floor(frames / 2), frames - 1]) {
        await p.evaluate((k) => window.dabsViewer.setFrame(k), f);
        await checkFitAndLabels(p, `3D view, frame ${f}`);
      }
      for (const view of ['plan', 'elevation']) {
        await p.evaluate((v) => window.dabsViewer.setView(v), view);
        await checkFitAndLabels(p, view);
      }
      await p.evaluate(() => window.dabsViewer.setView('3d'));
      // a joint whose label is hidden shows it when the pointer is over the joint, still without overlap
      const texts = await p.evaluate(() => window.dabsViewer.gapTexts());
      const shown = new Set((await p.evaluate(() => window.dabsViewer.visibleLabels())).map((l) => l.label));
      const hidden = texts.map((t) => t.split(':')[0]).findIndex((name) => !shown.has(name));
      if (hidden >= 0) {
        const q = await p.evaluate((k) => window.dabsViewer.jointPoint(k), hidden);
        await p.mouse.move(q.x, q.y);
        const after = await checkFitAndLabels(p, 'hover');
        const name = texts[hidden].split(':')[0];
        assert.ok(after.some((l) => l.label === name), `hovering joint ${name} does not show its label`);
      }
      await p.mouse.move(0, 0);
      await p.screenshot({ path: path.join(out, `viaduct${spans}.png`) });
    } finally {
      await p.close();
    }
  });
}
