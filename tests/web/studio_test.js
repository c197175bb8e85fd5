#!/usr/bin/env node
// ctest studio_page: the studio page in headless Chromium (Debian's chromium, driven by
// playwright-core pinned in web/package-lock.json). It starts `fsdb serve` on a free port with
// the demo catalogue, loads /, filters the shapes by name and opens one (a stored part's
// parameters in its structure), searches "a bnet cylinder" (read corrected) and "a pillow cylinder"
// (its offered word taken),
// searches "a very bent cylinder", waits for ranked thumbnails,
// opens the first result, moves the α slider, and takes screenshots that must not be blank and
// must change with α; then checks the object's address (a reload opens it again), the download
// links (GLB and STL fetched, the GLB through the Khronos glTF validator), and "More" on a search. Then the design tools, as a user would use
// them: a part from words; one fuzzy value dragged in the editor, the view following (a coarse
// preview, then the full mesh); the edit saved as version 2; versions 1 and 2 compared (the
// differing value marked, both envelopes in the view); the family's members, one clicked into
// the view; and a save after someone else stored a version (a 412 the page reports, with a
// reload). Each step's time is logged; each step's picture must not be blank.
// Any console error or failed request fails the test, but for the one deliberate 412 (the
// browser's own log line of it included).
// Usage: node studio_test.js FSDB_BINARY SOURCE_DIR WEB_DIR OUT_DIR VALIDATOR_DIR
//   (NODE_PATH: web-deps/node_modules; VALIDATOR_DIR: tools/gltf-validate/run-validator's WORK_DIR)
'use strict';
const { execFileSync } = require('child_process');
const fs = require('fs');
const path = require('path');
const { inkShare, newPage, regionShot, runPageTest, slowdown, watchProblems } = require('./helpers.js');

const [fsdb, source, webDir, out, validatorDir] = process.argv.slice(2);

// The design tools, step by step as a user would take them, each timed.
async function designTools(page, url, out, conflict) {
  const times = [];
  const step = async (name, body) => {
    const started = Date.now();
    const result = await body();
    times.push(`${name} ${Date.now() - started} ms`);
    return result;
  };
  const inks = [];
  // A picture of the view (or of `selector`) that must not be blank.
  const picture = async (name, selector = '#canvas-box') => {
    await page.waitForTimeout(300);
    const png = await page.locator(selector).screenshot({ path: path.join(out, `${name}.png`) });
    const ink = await inkShare(page, png);
    inks.push(`${name} ${ink.toFixed(4)}`);
    if (ink < 0.01) throw new Error(`the picture ${name} is blank`);
    return png;
  };
  const text = (selector) => page.$eval(selector, (e) => e.textContent);
  const region = (name, from, to) => regionShot(page, path.join(out, `${name}.png`), from, to);

  // A part from words, made by the form in "Create and import"; the view and the editor open it.
  const id = await step('part from words', async () => {
    await page.click('#tools summary');
    await page.fill('#words', 'a slightly bent cylinder');
    await page.press('#words', 'Enter');
    await page.waitForFunction(() => {
      const made = /^part .* \(#(\d+), version 1\)$/.exec(document.querySelector('#title').textContent);
      return made && (document.querySelector('#canvas').dataset.shown || '').startsWith(`part/${made[1]}@`);
    });
    return Number(/#(\d+)/.exec(await text('#title'))[1]);
  });
  await page.waitForSelector('#editor:not([hidden]) [data-action="edit-value"][data-value="params.kv"][data-field="core"]');
  const rows = await page.$$eval('#editor-values tr', (trs) => trs.map((tr) => tr.dataset.value));
  if (rows.length !== 14) throw new Error(`the editor shows ${rows.length} values: ${rows}`);
  // The words' fuzzy bend, resolved by the server, is in the editor as a trapezoid.
  const kvForm = await page.$eval('[data-action="edit-value"][data-value="params.kv"][data-field="form"]', (s) => s.value);
  if (kvForm !== 'trap') throw new Error(`kv's form: ${kvForm}`);
  const before = await picture('studio-edit-before');

  // Drag the bend: the view shows a coarse preview, then the full mesh, of the unsaved part, with
  // "computing…" over the last picture while a request is out.
  await page.evaluate(() => {
    const box = document.querySelector('#canvas-box');
    window.busySeen = false;
    new MutationObserver(() => { window.busySeen = window.busySeen || box.classList.contains('busy'); })
      .observe(box, { attributes: true, attributeFilter: ['class'] });
  });
  await step('edit a value: coarse preview', async () => {
    await page.locator('[data-action="edit-value"][data-value="params.kv"][data-field="core"]').fill('0.6');
    await page.waitForFunction(() => /^(coarse|fine):1$/.test(document.querySelector('#canvas').dataset.preview || ''));
  });
  await step('edit a value: full mesh', async () => {
    await page.waitForFunction(() => document.querySelector('#canvas').dataset.preview === 'fine:1');
  });
  if (!(await page.evaluate(() => window.busySeen))) throw new Error('no "computing…" while the preview was asked');
  if (await page.$eval('#canvas-box', (b) => b.classList.contains('busy'))) throw new Error('"computing…" stays after the answer');
  const afterEdit = await text('#view-status');
  if (afterEdit !== 'edited, not saved: α = 0.50') throw new Error(`view status after the edit: ${afterEdit}`);
  const log = await page.$eval('#canvas', (c) => c.dataset.previewLog);
  if (!log.startsWith('coarse:1')) throw new Error(`no coarse preview before the full mesh: ${log}`);
  const kvCore = await page.$$eval('[data-action="edit-value"][data-value="params.kv"]:not([data-field="form"]):not([data-field="core"])',
    (boxes) => boxes.map((b) => Number(b.value)));
  if (Math.abs((kvCore[1] + kvCore[2]) / 2 - 0.6) > 1e-9) throw new Error(`kv after the drag: ${kvCore}`);
  const edited = await picture('studio-edit');
  if (edited.equals(before)) throw new Error('the view does not follow the edit');
  await region('studio-editor', '#canvas-box', '#editor');

  // Save: version 2, stored with If-Match.
  await step('save version 2', async () => {
    await page.click('[data-action="save-version"]');
    await page.waitForFunction((want) => document.querySelector('#title').textContent.endsWith(want), `(#${id}, version 2)`);
    await page.waitForFunction(() => document.querySelector('#editor-status').textContent === 'saved as version 2');
  });
  const stored = await (await fetch(`${url}/parts/${id}/params`)).json();
  if (stored.version !== 2 || Math.abs((stored.params.kv.trap[1] + stored.params.kv.trap[2]) / 2 - 0.6) > 1e-9)
    throw new Error(`version 2 as stored: ${JSON.stringify(stored)}`);

  // History, and versions 1 and 2 compared: the bend is the one value marked, both in the view.
  await step('history', async () => {
    await page.click('[data-action="history"]');
    await page.waitForFunction(() => document.querySelectorAll('#version-list tr').length === 2);
  });
  // Version 1 opens in the view and in the editor.
  await step('open version 1', async () => {
    await page.click('#version-list tr[data-version="1"] [data-action="open-version"]');
    await page.waitForFunction(() => (document.querySelector('#canvas').dataset.shown || '').startsWith('version:1@') &&
      document.querySelector('#editor-status').textContent.startsWith('version 1 (of 2)'));
  });
  await picture('studio-version-1');
  await step('compare versions 1 and 2', async () => {
    await page.check('input[name="compare-a"][value="1"]');
    await page.check('input[name="compare-b"][value="2"]');
    await page.click('[data-action="compare"]');
    await page.waitForFunction(() => (document.querySelector('#canvas').dataset.shown || '').startsWith('compare:1,2@'));
  });
  const differing = await page.$$eval('#compare-values tr.differs', (trs) => trs.map((tr) => tr.firstChild.textContent));
  if (differing.length !== 1 || !differing[0].startsWith('kv')) throw new Error(`compared values that differ: ${differing}`);
  const compared = await picture('studio-compare');
  if (compared.equals(edited)) throw new Error('the comparison shows the same picture as one version');
  await region('studio-versions', '#canvas-box', '#versions');

  // The family's members, from the core outward; one clicked into the view.
  const degrees = await step('members gallery', async () => {
    await page.click('[data-action="members"]');
    await page.waitForFunction(() => document.querySelectorAll('#members > li').length === 9 &&
      [...document.querySelectorAll('#members > li')].every((li) => li.dataset.drawn === 'true'), null, { timeout: 60000 * slowdown });
    return page.$$eval('#members > li', (lis) => lis.map((li) => Number(li.dataset.membership)));
  });
  if (degrees[0] !== 1 || degrees.some((d, i) => i && d > degrees[i - 1])) throw new Error(`member degrees: ${degrees}`);
  const labels = await page.$$eval('#members .degree', (ds) => ds.map((d) => d.textContent));
  if (labels[0] !== 'μ = 1.00') throw new Error(`member labels: ${labels}`);
  await picture('studio-members', '#members-box');
  await step('show a member', async () => {
    await page.click('#members > li:nth-child(3)');
    await page.waitForFunction(() => document.querySelector('#canvas').dataset.shown === 'member:2');
  });
  await picture('studio-member');

  // Someone else stores a version after the page opened the part: the page's save is a 412,
  // reported with a reload that opens the current version.
  // (The page has version 2 open since the save.)
  const other = await fetch(`${url}/parts/${id}`, { method: 'PUT', headers: { 'If-Match': '"2"', 'Content-Type': 'application/json' },
    body: JSON.stringify({ kind: 'part', text: 'a very bent cylinder' }) });
  if (other.status !== 200) throw new Error(`the other client's save: ${other.status} ${await other.text()}`);
  // A trapezoid typed out of order is not sent: the editor says why and will not save it; put
  // back, it is previewed again.
  const kvA = '[data-action="edit-value"][data-value="params.kv"][data-field="a"]';
  const kvAWas = await page.$eval(kvA, (box) => box.value);
  const meshesBefore = await page.evaluate(() => performance.getEntriesByType('resource').filter((e) => e.name.endsWith('/mesh')).length);
  await page.fill(kvA, '0.9');
  await page.waitForFunction(() => document.querySelector('#editor-status').textContent === 'kv (bend) needs points in increasing order');
  if (!(await page.$eval('[data-action="save-version"]', (b) => b.disabled))) throw new Error('a disordered value can be saved');
  await page.waitForTimeout(800);  // past the full mesh's pause: still nothing asked
  const meshesAfter = await page.evaluate(() => performance.getEntriesByType('resource').filter((e) => e.name.endsWith('/mesh')).length);
  if (meshesAfter !== meshesBefore) throw new Error('a disordered value was sent');
  await page.fill(kvA, kvAWas);
  await page.waitForFunction(() => document.querySelector('#canvas').dataset.preview === 'fine:2');
  // This edit makes the crisp size fuzzy: core ± spread, the spread typed.
  await page.selectOption('[data-action="edit-value"][data-value="params.a1"][data-field="form"]', 'about');
  await page.fill('[data-action="edit-value"][data-value="params.a1"][data-field="spread"]', '0.2');
  await page.waitForFunction(() => document.querySelector('#canvas').dataset.preview === 'fine:4');
  conflict.expectConflict(true);
  await step('save after someone else: 412 reported', async () => {
    await page.click('[data-action="save-version"]');
    await page.waitForSelector('#editor[data-conflict="true"] [data-action="reload"]');
  });
  const said = await text('#editor-status');
  if (!/changed by someone else/.test(said) || !/Reload/.test(said)) throw new Error(`the conflict message: ${said}`);
  await picture('studio-conflict', '#editor');
  await step('reload after the conflict', async () => {
    await page.click('[data-action="reload"]');
    await page.waitForFunction((want) => document.querySelector('#title').textContent.endsWith(want), `(#${id}, version 3)`);
  });
  conflict.expectConflict(false);
  if (conflict.conflicts() !== 1) throw new Error(`412 answers seen: ${conflict.conflicts()}`);
  console.log(`design tools: ${times.join('; ')}`);
  console.log(`ink share of the design tools' pictures: ${inks.join(', ')}`);
}

async function main({ browser, url }) {
  fs.mkdirSync(out, { recursive: true });
  // While the test makes a save conflict on purpose, the one 412 answer to a PUT is expected (it
  // is counted), and so is the browser's own console line about it; nothing else is.
  let conflictExpected = false;
  let conflicts = 0;
  const page = await newPage(browser, { viewport: { width: 1280, height: 900 } });
  const problems = watchProblems(page, {
    console: (line) => conflictExpected && /the server responded with a status of 412/.test(line),
    response: (r) => {
      if (!(conflictExpected && r.status() === 412 && r.request().method() === 'PUT')) return false;
      conflicts += 1;
      return true;
    },
  });

  // Cold: the page and the list of shapes (thumbnails are drawn on first request, then cached).
  let started = Date.now();
  await page.goto(`${url}/`, { waitUntil: 'domcontentloaded' });
  await page.waitForSelector('#results > li img');
  const coldMillis = Date.now() - started;
  await page.waitForFunction(() => [...document.querySelectorAll('#results img')].every((i) => i.complete && i.naturalWidth > 0),
    null, { timeout: 60000 * slowdown });
  // Warm: everything, thumbnails included, from the server's cache. Reported, not asserted (the
  // goal, under 1 s, is a speed: docs/performance.md quotes it from a quiet run).
  started = Date.now();
  await page.reload({ waitUntil: 'load' });
  // The cards first: `every` holds on an empty list, and a slow server (the sanitizer build) had
  // not listed them yet when the filter below ran ("the filter shows 0 cards").
  await page.waitForSelector('#results > li img', { timeout: 60000 * slowdown });
  await page.waitForFunction(() => [...document.querySelectorAll('#results img')].every((i) => i.complete && i.naturalWidth > 0),
    null, { timeout: 60000 * slowdown });
  const loadMillis = Date.now() - started;
  // Browsing: the name filter, and a stored part's parameters in the structure of a shape.
  await page.fill('#filter', 'snowman');
  const visible = await page.$$eval('#results > li', (items) => items.filter((li) => !li.hidden).map((li) => li.dataset.id));
  if (visible.length !== 1) throw new Error(`the filter shows ${visible.length} cards`);
  await page.click('#results > li:not([hidden])');
  await page.waitForFunction(() => document.querySelector('#tree').textContent.includes('a1 = 2'));
  await page.fill('#filter', '');

  // A misspelt word (no dictionary word) is read corrected, and the reading says so.
  await page.fill('#query', 'a bnet cylinder');
  await page.press('#query', 'Enter');
  await page.waitForFunction(() => document.querySelector('#read-as').textContent.includes('read “bnet” as “bent” (spelling, scores × 0.95)'));
  const reading = await page.$eval('#read-as', (p) => p.textContent);
  if (!reading.includes('Searched for “a bent cylinder”')) throw new Error(`reading: ${reading}`);
  // A dictionary word is left out, its near words offered, each one click away.
  await page.fill('#query', 'a pillow cylinder');
  await page.press('#query', 'Enter');
  await page.waitForSelector('#read-as a[data-action="correct-word"]');
  const left = await page.$eval('#read-as', (p) => p.textContent);
  if (!left.includes('not understood: “pillow” (pillar')) throw new Error(`reading: ${left}`);
  await page.click('#read-as a[data-action="correct-word"]');
  // Its search done ("cylinder" beside a pillar is no longer read) before the next one starts.
  await page.waitForFunction(() => document.querySelector('#query').value === 'a pillar cylinder' &&
    document.querySelector('#read-as').textContent.includes('not understood: “cylinder”') &&
    document.querySelector('#status').textContent.includes('linguistic search'));

  await page.fill('#query', 'a very bent cylinder');
  await page.press('#query', 'Enter');
  await page.waitForFunction(() => document.querySelector('#status').textContent.includes('linguistic search') &&
    document.querySelector('#read-as').textContent.includes('very bent'));
  const ranked = await page.$$eval('#results > li', (items) => items.map((li) => ({
    name: li.querySelector('.name').childNodes[0].textContent,
    score: Number(li.querySelector('.score').textContent),
  })));
  if (ranked.length < 3) throw new Error(`expected ranked results, got ${JSON.stringify(ranked)}`);
  for (let i = 1; i < ranked.length; i++)
    if (ranked[i].score > ranked[i - 1].score) throw new Error(`not ranked: ${JSON.stringify(ranked)}`);
  // Every thumbnail loaded (a decoded image has a natural width).
  await page.waitForFunction(() => [...document.querySelectorAll('#results img')].every((i) => i.complete && i.naturalWidth > 0));
  await page.screenshot({ path: path.join(out, 'studio-search.png') });

  // The first shape among the results (the view shows shapes and parts alike).
  const first = await page.$eval('#results > li', (li) => `${li.dataset.kind}/${li.dataset.id}`);
  const shown = (alpha) => page.waitForFunction((want) => document.querySelector('#canvas').dataset.shown === want,
    `${first}@${alpha}`);
  await page.click('#results > li');
  await page.waitForSelector('#view:not([hidden])');
  await shown('0.5');
  // The coarse preview came first and the status line says what the view shows now.
  const coarse = await page.$eval('#canvas', (c) => c.dataset.coarse);
  if (coarse !== `${first}@0.5`) throw new Error(`no coarse preview before the full mesh: ${coarse}`);
  const viewStatus = await page.$eval('#view-status', (p) => p.textContent);
  if (!/^α = 0\.50 \(\d+\.\d s\)$/.test(viewStatus)) throw new Error(`view status: ${viewStatus}`);
  await page.waitForSelector('#chart path[stroke="#eb8232"]');
  await page.waitForTimeout(300);
  const atHalf = await page.locator('#canvas-box').screenshot({ path: path.join(out, 'studio-alpha-0.5.png') });
  await page.locator('#alpha').fill('1');
  await shown('1');
  await page.waitForTimeout(300);
  const atOne = await page.locator('#canvas-box').screenshot({ path: path.join(out, 'studio-alpha-1.png') });
  await page.locator('#alpha').fill('0');
  await shown('0');
  await page.waitForTimeout(300);
  const atZero = await page.locator('#canvas-box').screenshot({ path: path.join(out, 'studio-alpha-0.png') });
  await page.screenshot({ path: path.join(out, 'studio-view.png') });

  // The object's address, and the download links at the slider's α (fetched as the browser
  // would download them: a GLB of both bounds, an STL of upper).
  const [kindOf, idOf] = first.split('/');
  const address = await page.evaluate(() => location.hash);
  if (address !== `#/${kindOf}s/${idOf}`) throw new Error(`address: ${address}`);
  const glbHref = await page.$eval('[data-action="export-glb"]', (a) => a.getAttribute('href'));
  if (glbHref !== `/${kindOf}s/${idOf}/mesh?format=glb&alpha=0`) throw new Error(`GLB link: ${glbHref}`);
  const fetched = (href) => page.evaluate(async (h) => {
    const r = await fetch(h);
    const b = new Uint8Array(await r.arrayBuffer());
    return { status: r.status, magic: String.fromCharCode(...b.slice(0, 4)), size: b.length, disposition: r.headers.get('content-disposition') };
  }, href);
  const glb = await fetched(glbHref);
  if (glb.status !== 200 || glb.magic !== 'glTF' || !/^attachment/.test(glb.disposition || '')) throw new Error(`GLB download: ${JSON.stringify(glb)}`);
  // The downloaded file, as the user gets it, through the Khronos glTF validator the
  // gltf_validator ctest uses (tools/gltf-validate): valid, with its lower and upper meshes.
  const glbBytes = await page.evaluate(async (h) => {
    const b = new Uint8Array(await (await fetch(h)).arrayBuffer());
    let s = '';
    for (let i = 0; i < b.length; i += 0x8000) s += String.fromCharCode(...b.subarray(i, i + 0x8000));
    return btoa(s);
  }, glbHref);
  const glbFile = path.join(out, 'download.glb');
  fs.writeFileSync(glbFile, Buffer.from(glbBytes, 'base64'));
  execFileSync(path.join(source, 'tools/gltf-validate/run-validator'), [fsdb, validatorDir, glbFile], { stdio: 'inherit' });
  const stl = await fetched(await page.$eval('[data-action="export-stl"][data-bound="upper"]', (a) => a.getAttribute('href')));
  if (stl.status !== 200 || stl.size < 84) throw new Error(`STL download: ${JSON.stringify(stl)}`);
  for (const action of ['export-obj', 'export-vdb'])
    if (!(await page.$eval(`[data-action="${action}"]`, (a) => a.getAttribute('href')))) throw new Error(`no ${action} link`);
  // A reload (or a shared link) opens the object from its address.
  await page.reload({ waitUntil: 'load' });
  await page.waitForFunction((id) => !document.querySelector('#view').hidden &&
    document.querySelector('#title').textContent.includes(`(#${id},`), idOf);

  // "More" asks for 12 results more.
  await page.fill('#query', 'something');
  await page.press('#query', 'Enter');
  await page.waitForFunction(() => document.querySelector('#status').textContent.includes('12 results'));
  await page.waitForSelector('[data-action="more-results"]:not([hidden])');
  await page.click('[data-action="more-results"]');
  await page.waitForFunction(() => document.querySelectorAll('#results > li').length > 12);

  await designTools(page, url, out, {
    expectConflict: (on) => { conflictExpected = on; },
    conflicts: () => conflicts,
  });

  const inks = [await inkShare(page, atZero), await inkShare(page, atHalf), await inkShare(page, atOne)];
  console.log(`page and list in ${coldMillis} ms cold; page with every thumbnail in ${loadMillis} ms warm; results ${ranked.map((r) => `${r.name} ${r.score}`).join(', ')}`);
  console.log(`ink share at alpha 0 / 0.5 / 1: ${inks.map((x) => x.toFixed(4)).join(' / ')}`);
  if (inks.some((x) => x < 0.01)) throw new Error('a view screenshot is blank');
  if (atZero.equals(atOne) || atHalf.equals(atOne)) throw new Error('the view does not change with alpha');
  if (problems.length) throw new Error(problems.join('\n'));
  console.log('studio page: ok');
}

runPageTest(fsdb, source, webDir, main);
