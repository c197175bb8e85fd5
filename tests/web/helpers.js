// What the studio's page tests share: a real `fsdb serve` with the demo catalogue on a free port,
// Debian's chromium, and the ink share of a screenshot (a blank picture is a failure).
'use strict';
const { spawn } = require('child_process');
const fs = require('fs');
const os = require('os');
const path = require('path');
const { chromium } = require('playwright-core');

// How many times slower than a Release build the server under test runs (FSDB_SLOWDOWN: the
// sanitizer build sets it, tests/CMakeLists.txt); every wait scales with it.
const slowdown = Number(process.env.FSDB_SLOWDOWN || '1');

// The server's time limit per evaluation scales with the slowdown as every wait does: under the
// sanitizers (8x) a view of a fuzzy demo part may need more than the default 60 s, and a build
// now stops within a search of its deadline instead of finishing the block it is in.
function startServer(fsdb, source, webDir) {
  const dir = fs.mkdtempSync(path.join(os.tmpdir(), 'fsdb-studio-'));
  const child = spawn(fsdb, ['--log-level', 'warn', 'serve', '--port', '0', '--db', path.join(dir, 'db.sqlite'),
    '--demo', path.join(source, 'schema/demo'), '--web', webDir, '--max-eval-ms', String(60000 * slowdown)],
  { stdio: ['ignore', 'pipe', 'inherit'] });
  return new Promise((resolve, reject) => {
    let buffered = '';
    child.stdout.on('data', (chunk) => {
      buffered += chunk;
      const match = buffered.match(/listening on (http:\/\/[^\s]+)/);
      if (match) resolve({ child, url: match[1] });
    });
    child.on('exit', (code) => reject(new Error(`fsdb serve exited with ${code}`)));
  });
}

// Headless chromium with software WebGL (SwiftShader).
function launchBrowser() {
  return chromium.launch({
    executablePath: process.env.CHROMIUM || '/usr/bin/chromium',
    args: ['--no-sandbox', '--use-angle=swiftshader', '--enable-unsafe-swiftshader', '--ignore-gpu-blocklist'],
  });
}

// Share of pixels that differ from the page background (white), from a PNG screenshot decoded in
// the page itself (no image library needed here).
async function inkShare(page, png) {
  return page.evaluate(async (b64) => {
    const img = new Image();
    img.src = `data:image/png;base64,${b64}`;
    await img.decode();
    const c = document.createElement('canvas');
    c.width = img.width;
    c.height = img.height;
    const g = c.getContext('2d');
    g.drawImage(img, 0, 0);
    const d = g.getImageData(0, 0, c.width, c.height).data;
    let ink = 0;
    for (let i = 0; i < d.length; i += 4) if (d[i] < 240 || d[i + 1] < 240 || d[i + 2] < 240) ink++;
    return ink / (d.length / 4);
  }, png.toString('base64'));
}

// Every console error, page error, failed request and answer of 400 or more, listed in the array
// returned; but for a thumbnail still loading when its card is replaced (a new search, "More", a
// reload: the browser aborts it, as for any user), and what `expected` allows (a test's deliberate
// 412 and the browser's own console line of it).
function watchProblems(page, expected = {}) {
  const allowedLine = expected.console || (() => false);
  const allowedAnswer = expected.response || (() => false);
  const problems = [];
  page.on('console', (m) => {
    if (m.type() === 'error' && !allowedLine(m.text())) problems.push(`console: ${m.text()}`);
  });
  page.on('pageerror', (e) => problems.push(`page error: ${e.message}`));
  page.on('requestfailed', (r) => {
    if (r.failure().errorText === 'net::ERR_ABORTED' && /\/thumbnail\.png$/.test(new URL(r.url()).pathname)) return;
    problems.push(`request failed: ${r.url()} ${r.failure().errorText}`);
  });
  page.on('response', (r) => {
    if (r.status() >= 400 && !allowedAnswer(r)) problems.push(`HTTP ${r.status()}: ${r.url()}`);
  });
  return problems;
}

// A picture of the page from the top of `from` to the bottom of `to`, as wide as the view, into
// `file` (for docs/images: the view with the tool under it).
async function regionShot(page, file, from, to) {
  const [a, b, view] = await Promise.all([from, to, '#view'].map((sel) => page.$eval(sel, (e) => {
    const r = e.getBoundingClientRect();
    return { x: r.x + window.scrollX, y: r.y + window.scrollY, width: r.width, height: r.height };
  })));
  await page.screenshot({ path: file, fullPage: true, clip: { x: view.x, y: a.y, width: view.width, height: b.y + b.height - a.y } });
}


// A page whose waits (Playwright's default 30 s) scale with the slowdown.
async function newPage(browser, options) {
  const page = await browser.newPage(options);
  page.setDefaultTimeout(30000 * slowdown);
  return page;
}

// Runs a page test: body({ browser, url }) against a fresh server (startServer) in a fresh browser,
// both closed however it ends; a failure ends the process with status 1 and its message.
function runPageTest(fsdb, source, webDir, body) {
  (async () => {
    const { child, url } = await startServer(fsdb, source, webDir);
    const browser = await launchBrowser();
    try {
      await body({ browser, url });
    } finally {
      await browser.close();
      child.kill('SIGTERM');
    }
  })().catch((e) => { console.error(e.message || e); process.exit(1); });
}

module.exports = { runPageTest, startServer, launchBrowser, inkShare, watchProblems, regionShot, newPage, slowdown };
