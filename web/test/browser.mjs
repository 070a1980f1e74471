// The browser the tests drive: Debian's chromium through puppeteer-core (no browser download),
// headless, WebGL drawn by SwiftShader (docs/viewer.md). Pages are opened from file://, as a user
// opens them, without --allow-file-access-from-files.
import puppeteer from 'puppeteer-core';
import { existsSync } from 'node:fs';
import { pathToFileURL } from 'node:url';

export const CHROMIUM = process.env.TECIDO_CHROMIUM || '/usr/bin/chromium';

export function browserMissing() {
  return existsSync(CHROMIUM) ? '' : `no browser at ${CHROMIUM} (apt-get install chromium, or set TECIDO_CHROMIUM)`;
}

export async function launch() {
  return puppeteer.launch({
    executablePath: CHROMIUM,
    args: ['--headless', '--no-sandbox', '--use-angle=swiftshader', '--enable-unsafe-swiftshader', '--window-size=1200,800'],
    defaultViewport: { width: 1200, height: 800 },
  });
}

/// Opens `file` (a path); returns the page and what it reported: console errors, page errors
/// (uncaught exceptions), dialogs (alert() and its kin: a user's text that ran), failed requests.
export async function open(browser, file) {
  const page = await browser.newPage();
  const report = { errors: [], dialogs: [] };
  page.on('console', (m) => {
    if (m.type() === 'error' || m.type() === 'warn') report.errors.push(`console.${m.type()}: ${m.text()}`);
  });
  page.on('pageerror', (e) => report.errors.push(`page error: ${e.message}`));
  page.on('requestfailed', (r) => report.errors.push(`request failed: ${r.url()} ${r.failure()?.errorText}`));
  page.on('dialog', async (d) => {
    report.dialogs.push(d.message());
    await d.dismiss();
  });
  const t0 = performance.now();
  await page.goto(pathToFileURL(file).href, { waitUntil: 'load' });
  report.loadMs = performance.now() - t0;
  return { page, report };
}

/// Waits until the viewer has drawn (window.tecidoView set), returns the milliseconds since `t0`.
export async function viewerReady(page) {
  await page.waitForFunction(() => window.tecidoView !== undefined, { timeout: 20000 });
}

/// The WebGL canvas read back (drawn into a 2-D canvas): the number of distinct colours among
/// sampled pixels and the share of pixels that differ from the corner's (the background).
export async function canvasStats(page) {
  return page.evaluate(() => {
    const gl = document.querySelector('#stage canvas');
    if (!gl) return { colours: 0, drawn: 0 };
    const c = document.createElement('canvas');
    c.width = gl.width;
    c.height = gl.height;
    const ctx = c.getContext('2d');
    ctx.drawImage(gl, 0, 0);
    const px = ctx.getImageData(0, 0, c.width, c.height).data;
    const bg = [px[0], px[1], px[2]];
    const colours = new Set();
    let drawn = 0, n = 0;
    for (let i = 0; i < px.length; i += 4 * 7) {
      ++n;
      colours.add((px[i] << 16) | (px[i + 1] << 8) | px[i + 2]);
      if (Math.abs(px[i] - bg[0]) + Math.abs(px[i + 1] - bg[1]) + Math.abs(px[i + 2] - bg[2]) > 12) ++drawn;
    }
    return { colours: colours.size, drawn: drawn / n };
  });
}

/// Moves the page's range input #frame to `value` as a user's drag does (an input event).
export async function moveSlider(page, value) {
  await page.evaluate((v) => {
    const s = document.getElementById('frame');
    s.value = String(v);
    s.dispatchEvent(new Event('input', { bubbles: true }));
  }, value);
}
