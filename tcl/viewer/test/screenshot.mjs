// SPDX-License-Identifier: MIT
// Screenshots of a Viewer page at the frame of the largest total contact (pounding) force, in the
// 3D, plan, elevation and joint views, by headless Chromium through playwright-core:
//   node screenshot.mjs page.html outDir prefix
// writes outDir/prefix-{3d,plan,elevation,joint}.png and prints "frame F time T force N".
// DABS_VIEWER_MODULES names the node_modules folder holding playwright-core. The bridge report
// (verification/bridge/tools/report.tcl) embeds the pictures; the browser test runs it too.
import { createRequire } from 'node:module';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { fileURLToPath } from 'node:url';

const kViews = ['3d', 'plan', 'elevation', 'joint'];

/** Opens `page` in headless Chromium; returns { context, page }. */
export async function openPage(file, modules, viewport = { width: 1400, height: 800 }) {
  const require = createRequire(path.join(modules || '', 'x.js'));
  const { chromium } = require('playwright-core');
  const profile = fs.mkdtempSync(path.join(os.tmpdir(), 'dabs-viewer-chromium-'));
  const context = await chromium.launchPersistentContext(profile, {
    executablePath: '/usr/bin/chromium',
    headless: true,
    viewport,
    args: ['--headless', '--no-sandbox', '--disable-gpu', '--disable-quic', '--no-first-run',
      '--disable-background-networking', '--disable-component-update', '--disable-sync'],
  });
  // The profile is the browser's own files: gone with the browser.
  context.on('close', () => fs.rmSync(profile, { recursive: true, force: true }));
  const page = await context.newPage();
  await page.goto('file://' + path.resolve(file));
  await page.waitForFunction(() => window.dabsViewer !== undefined, null, { timeout: 30000 });
  return { context, page };
}

/** Sets the frame of the largest contact force and saves one screenshot per view. */
export async function screenshots(page, outDir, prefix) {
  const frame = await page.evaluate(() => window.dabsViewer.frameOfMaxContactForce());
  await page.evaluate((f) => window.dabsViewer.setFrame(f), frame);
  const files = [];
  for (const view of kViews) {
    const shown = await page.evaluate((v) => {
      const b = document.querySelector(`#views button[data-view="${v}"]`);
      if (!b || b.style.display === 'none') return false;
      window.dabsViewer.setView(v);
      return true;
    }, view);
    if (!shown) continue;
    const file = path.join(outDir, `${prefix}-${view}.png`);
    await page.screenshot({ path: file });
    files.push(file);
  }
  await page.evaluate(() => window.dabsViewer.setView('3d'));
  const time = await page.evaluate((f) => window.dabsViewer.time(f), frame);
  const force = await page.evaluate((f) => window.dabsViewer.contactForceTotal(f), frame);
  return { frame, time, force, files };
}

if (process.argv[1] === fileURLToPath(import.meta.url)) {
  const [file, outDir, prefix] = process.argv.slice(2);
  if (!file || !outDir || !prefix) {
    console.error('usage: node screenshot.mjs page.html outDir prefix');
    process.exit(2);
  }
  const { context, page } = await openPage(file, process.env.DABS_VIEWER_MODULES);
  try {
    const ready = await page.evaluate(() => window.dabsViewer.ready);
    if (!ready) throw new Error('viewer failed: ' + (await page.evaluate(() => window.dabsViewer.error)));
    const r = await screenshots(page, outDir, prefix);
    console.log(`frame ${r.frame} time ${r.time} force ${r.force}`);
  } finally {
    await context.close();
  }
}
