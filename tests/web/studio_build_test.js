#!/usr/bin/env node
// ctest studio_build: the studio as a design tool, in headless Chromium against a real
// `fsdb serve` with the demo catalogue, as a user would take it: builds a shape of two parts from
// words, the second placed "about 3" units "right" of the first (the example), sees the
// unsaved tree in the view, saves it and sees it opened; opens a Bézier curve (its lower, crisp and
// upper curves, changing with α) and a fair curve, picks a candidate other than the best (stored
// as a new version; a reload shows the choice marked and drawn); opens a surface (lower and upper
// with their control nets); searches with a word corrected in one click, a word read as another
// (shown with the results) and a least score; and loads the page on a phone (390×844) and a tablet (768×1024), where
// the view, the search box and the α slider must be visible and nothing wider than the screen.
// Each step is timed and its picture must not be blank; any console error, failed request or
// answer of 400 or more fails the test.
// Usage: node studio_build_test.js FSDB_BINARY SOURCE_DIR WEB_DIR OUT_DIR   (NODE_PATH: web-deps/node_modules)
'use strict';
const fs = require('fs');
const path = require('path');
const { isDeepStrictEqual } = require('util');
const { inkShare, newPage, regionShot, runPageTest, slowdown, watchProblems } = require('./helpers.js');

const [fsdb, source, webDir, out] = process.argv.slice(2);

async function main({ browser, url }) {
  fs.mkdirSync(out, { recursive: true });
  const times = [];
  const inks = [];
  const page = await newPage(browser, { viewport: { width: 1280, height: 900 } });
  // Words with a misspelling are refused when added (the one 422 expected, and the browser's
  // console line of it); nothing else may fail.
  let unknownWords = false;
  let refused = 0;
  const problems = watchProblems(page, {
    console: (line) => unknownWords && /the server responded with a status of 422/.test(line),
    response: (r) => {
      if (!(unknownWords && r.status() === 422 && new URL(r.url()).pathname === '/mesh')) return false;
      refused += 1;
      return true;
    },
  });
  const step = async (name, body) => {
    const started = Date.now();
    const result = await body().catch((e) => { throw new Error(`${name}: ${e.message}`); });
    times.push(`${name} ${Date.now() - started} ms`);
    return result;
  };
  // A picture of `selector` (the view by default) that must not be blank.
  const picture = async (name, selector = '#canvas-box', least = 0.01) => {
    await page.waitForTimeout(300);
    const png = await page.locator(selector).screenshot({ path: path.join(out, `${name}.png`) });
    const ink = await inkShare(page, png);
    inks.push(`${name} ${ink.toFixed(4)}`);
    if (ink < least) throw new Error(`the picture ${name} is blank`);
    return png;
  };
  const region = (name, from, to) => regionShot(page, path.join(out, `${name}.png`), from, to);
  const text = (selector) => page.$eval(selector, (e) => e.textContent);
  const shown = () => page.$eval('#canvas', (c) => c.dataset.shown || '');

  await page.goto(`${url}/`, { waitUntil: 'load' });
  await page.waitForSelector('#results > li');

  // ---- 1. Build a shape: "a big box" and "a slightly bent cylinder" about 3 units right of it.
  await step('build: start', async () => {
    await page.click('[data-action="new-shape"]');
    await page.waitForSelector('#view[data-mode="draft"] #builder [data-action="add-part"]');
  });
  await step('build: add a big box (from words)', async () => {
    await page.selectOption('#add-source', 'words');
    await page.fill('#add-text', 'a big box');
    await page.click('[data-action="add-part"]');
    await page.waitForSelector('#tree li[data-node="part"][data-name="big-box"]');
  });
  await step('build: words with a misspelling refused, with the closest words', async () => {
    unknownWords = true;
    await page.fill('#add-text', 'a slighly bent cylinder');
    await page.click('[data-action="add-part"]');
    await page.waitForFunction(() => /unknown word 'slighly'.*slightly/.test(document.querySelector('#builder-status').textContent));
    unknownWords = false;
  });
  if (refused !== 1 || (await page.$$('#tree li[data-node="part"]')).length !== 1) throw new Error(`misspelt words: ${refused} refusals`);
  const oneStatus = await text('#view-status');
  if (!/needs at least two parts/.test(oneStatus)) throw new Error(`one part in a union: ${oneStatus}`);
  await step('build: add a slightly bent cylinder, preview', async () => {
    await page.fill('#add-text', 'a slightly bent cylinder');
    await page.click('[data-action="add-part"]');
    await page.waitForSelector('#tree li[data-node="part"][data-name="slightly-bent-cylinder"]');
    await page.waitForFunction(() => (document.querySelector('#canvas').dataset.shown || '').startsWith('draft:'), null, { timeout: 60000 * slowdown });
  });
  const unplaced = await picture('studio-build-unplaced');
  await step('build: place the cylinder about 3 right of the box, preview', async () => {
    const was = await shown();
    await page.click('#tree li[data-name="slightly-bent-cylinder"] [data-action="place"]');
    const placed = '#tree li[data-name="slightly-bent-cylinder"] .placement';
    await page.waitForSelector(placed);
    const against = await page.$eval(`${placed} [data-field="relative_to"]`, (s) => s.value);
    if (against !== 'big-box') throw new Error(`placed against ${against}`);
    await page.selectOption(`${placed} [data-field="direction"]`, 'right');
    await page.fill(`${placed} [data-field="distance"]`, 'about 3');
    await page.press(`${placed} [data-field="distance"]`, 'Enter');
    await page.waitForFunction((w) => {
      const s = document.querySelector('#canvas').dataset.shown || '';
      return s.startsWith('draft:') && s !== w;
    }, was, { timeout: 60000 * slowdown });
    await page.waitForFunction(() => document.querySelector('#view-status').textContent.startsWith('new shape, not saved'));
  });
  const placedPicture = await picture('studio-build');
  if (placedPicture.equals(unplaced)) throw new Error('the view does not follow the placement');
  // The operation of the root node is chosen in the tree; the preview follows (and comes back).
  await step('build: difference, then union again', async () => {
    for (const op of ['difference', 'union']) {
      const was = await shown();
      await page.selectOption('#tree li[data-node="op"] > [data-action="set-op"]', op);
      await page.waitForFunction((w) => {
        const s = document.querySelector('#canvas').dataset.shown || '';
        return s.startsWith('draft:') && s !== w;
      }, was, { timeout: 60000 * slowdown });
    }
  });
  await region('studio-builder', '#canvas-box', '#panels');
  const name = `box-and-cylinder-${Date.now().toString(36)}`;
  const id = await step('build: save and open', async () => {
    await page.fill('#shape-name', name);
    await page.click('[data-action="save-shape"]');
    await page.waitForFunction((n) => document.querySelector('#title').textContent.startsWith(`shape ${n} (#`) &&
      (document.querySelector('#canvas').dataset.shown || '').startsWith('shape/'), name, { timeout: 60000 * slowdown });
    return Number(/#(\d+)/.exec(await text('#title'))[1]);
  });
  const stored = await (await fetch(`${url}/shapes/${id}`)).json();
  const tree = stored.document.tree;
  const want = { op: 'union', children: [{ part: { name: 'big-box', text: 'a big box' } },
    { part: { name: 'slightly-bent-cylinder', text: 'a slightly bent cylinder' },
      transform: { place: { relative_to: 'big-box', direction: 'right', distance: 'about 3' } } }] };
  if (!isDeepStrictEqual(tree, want)) throw new Error(`the stored tree: ${JSON.stringify(tree)}`);
  if ((await page.evaluate(() => location.hash)) !== `#/shapes/${id}`) throw new Error('the saved shape is not opened at its address');
  await picture('studio-build-saved');

  // The other two sources of parts: the catalogue's cube (referenced by name) and a new unit
  // sphere, the sphere placed 1 unit above the cube's centre (it cuts into the cube's top), the
  // root a difference.
  await step('build: a catalogue part and a new one, a difference', async () => {
    await page.click('[data-action="new-shape"]');
    await page.waitForFunction(() => document.querySelector('#view').dataset.mode === 'draft' && !document.querySelector('#tree li[data-node="part"]'));
    await page.selectOption('#add-source', 'catalogue');
    await page.fill('#add-text', 'cube');
    await page.click('[data-action="add-part"]');
    await page.waitForSelector('#tree li[data-node="part"][data-name="cube"]');
    await page.selectOption('#add-source', 'new');
    await page.click('[data-action="add-part"]');
    await page.waitForSelector('#tree li[data-node="part"][data-name="sphere"]');
    await page.click('#tree li[data-name="sphere"] [data-action="place"]');
    await page.selectOption('#tree li[data-name="sphere"] .placement [data-field="direction"]', 'top');
    await page.fill('#tree li[data-name="sphere"] .placement [data-field="distance"]', '1');
    await page.press('#tree li[data-name="sphere"] .placement [data-field="distance"]', 'Enter');
    await page.selectOption('#tree li[data-node="op"] > [data-action="set-op"]', 'difference');
    await page.waitForFunction(() => document.querySelector('#view-status').textContent.startsWith('new shape, not saved'), null, { timeout: 60000 * slowdown });
  });
  // An operation nested under the root waits for its two operands; removed, the tree previews again.
  await step('build: a nested operation added and removed', async () => {
    await page.click('[data-action="add-operation"]');
    await page.waitForFunction(() => document.querySelectorAll('#tree li[data-node="op"]').length === 2 &&
      /the difference needs at least two parts \(it has 0\)/.test(document.querySelector('#view-status').textContent));
    await page.click('#tree li[data-node="op"] li[data-node="op"] > [data-action="remove-node"]');
    await page.waitForFunction(() => document.querySelectorAll('#tree li[data-node="op"]').length === 1 &&
      document.querySelector('#view-status').textContent.startsWith('new shape, not saved'), null, { timeout: 60000 * slowdown });
  });
  await picture('studio-build-difference');
  const draft = await page.evaluate(() => document.querySelector('#tree').textContent);
  if (!/difference/.test(draft) || !/from the catalogue/.test(draft) || !/a unit sphere/.test(draft)) throw new Error(`the draft: ${draft}`);

  // ---- 2. Curves and surfaces.
  const openCard = async (kind, name) => {
    await page.click(`[data-browse="${kind}s"]`);
    await page.waitForSelector(`#results > li[data-kind="${kind}"]`);
    const card = page.locator(`#results > li[data-kind="${kind}"]`, { hasText: name });
    const cardId = Number(await card.getAttribute('data-id'));
    await card.click();
    return cardId;
  };
  const curveShown = (want) => page.waitForFunction((w) => document.querySelector('#curve-svg').dataset.shown === w, want);
  const waveId = await step('curve: open a Bezier curve', async () => {
    const cid = await openCard('curve', 'fuzzy-wave');
    await curveShown(`curve/${cid}@0.5`);
    return cid;
  });
  const wave = await picture('studio-curve', '#curve-box');
  await step('curve: alpha 0', async () => {
    await page.locator('#alpha').fill('0');
    await curveShown(`curve/${waveId}@0`);
  });
  const waveAtZero = await picture('studio-curve-alpha-0', '#curve-box');
  await region('studio-curve-view', '#curve-box', '#alpha-box');
  if (waveAtZero.equals(wave)) throw new Error('the curve does not change with alpha');
  const fairId = await step('fair curve: open, candidates', async () => {
    const cid = await openCard('curve', 'fair-figure-7');
    await page.waitForFunction(() => document.querySelectorAll('#candidates > li').length >= 2);
    await curveShown(`curve/${cid}#0`);
    return cid;
  });
  if (await page.$('#candidates > li.chosen')) throw new Error('a candidate is marked chosen before any choice');
  await step('fair curve: choose candidate 2 (a new version)', async () => {
    await page.click('#candidates > li[data-candidate="1"] [data-action="choose-candidate"]');
    await page.waitForFunction((n) => document.querySelector('#title').textContent.endsWith(`(#${n}, version 2)`) &&
      document.querySelector('#candidates > li[data-candidate="1"].chosen'), fairId);
    await curveShown(`curve/${fairId}#1`);
  });
  const storedCurve = await (await fetch(`${url}/curves/${fairId}`)).json();
  if (storedCurve.document.chosen_candidate !== 1 || storedCurve.version !== 2) throw new Error(`the stored choice: ${JSON.stringify(storedCurve)}`);
  await step('fair curve: reload shows the choice', async () => {
    await page.reload({ waitUntil: 'load' });
    await page.waitForFunction(() => document.querySelector('#candidates > li[data-candidate="1"].chosen .mark'));
    await curveShown(`curve/${fairId}#1`);
  });
  await picture('studio-fair-curve', '#curve-box');
  await region('studio-candidates', '#curve-box', '#candidates-box');
  await step('surface: open, lower and upper with control nets', async () => {
    const sid = await openCard('surface', 'fuzzy-saddle');
    await page.waitForFunction((w) => (document.querySelector('#canvas').dataset.shown || '').startsWith(w), `surface/${sid}@`);
  });
  await picture('studio-surface');

  // ---- 3. Search polish: a correction word in one click, the words read otherwise shown with the
  // results, and the least score.
  const searched = (want) => page.waitForFunction((w) => document.querySelector('#query').value === w &&
    /result.*linguistic search/.test(document.querySelector('#status').textContent), want);
  await step('search: a misspelt word read corrected', async () => {
    await page.fill('#query', 'a bnet cylinder');
    await page.press('#query', 'Enter');
    await searched('a bnet cylinder');
    await page.waitForFunction(() => document.querySelector('#read-as').textContent.includes('read “bnet” as “bent” (spelling'));
  });
  await step('search: a word read as another (WordNet)', async () => {
    await page.fill('#query', 'a crooked cylinder');
    await page.press('#query', 'Enter');
    await page.waitForFunction(() => document.querySelector('#read-as').textContent.includes('“crooked”'));
  });
  const reading = await text('#read-as');
  if (!reading.includes('Read as: find a bent cylinder') || !reading.includes('read “crooked” as “bent” (WordNet antonym, scores × 0.85)'))
    throw new Error(`the reading: ${reading}`);
  const scores = () => page.$$eval('#results > li .score', (ss) => ss.map((x) => Number(x.textContent)));
  await step('search: least score 0.5', async () => {
    await page.fill('#query', 'a slightly bent cylinder');
    await page.press('#query', 'Enter');
    await searched('a slightly bent cylinder');
    const all = await scores();
    if (!all.some((x) => x < 0.5)) throw new Error(`no score under 0.5 to leave out: ${all}`);
    await page.locator('#threshold').fill('0.5');
    await page.waitForFunction(() => document.querySelector('#status').textContent.includes('scoring at least 0.50'));
    const kept = await scores();
    if (!kept.length || kept.some((x) => x < 0.5) || kept.length >= all.length) throw new Error(`at least 0.5: ${kept} of ${all}`);
  });
  await page.waitForFunction(() => [...document.querySelectorAll('#results img')].every((i) => i.complete && i.naturalWidth > 0),
    null, { timeout: 60000 * slowdown });
  await page.screenshot({ path: path.join(out, 'studio-search-polish.png'), clip: { x: 0, y: 0, width: 1280, height: 520 } });
  await page.locator('#threshold').fill('0');

  // ---- 4. Phone and tablet: the view (a shape opened from its address), the search box and the
  // α slider are visible and within the screen's width, and nothing makes the page scroll sideways.
  for (const [label, width, height] of [['phone', 390, 844], ['tablet', 768, 1024]]) {
    await step(`layout: ${label} ${width}x${height}`, async () => {
      const small = await newPage(browser, { viewport: { width, height }, isMobile: label === 'phone', hasTouch: true });
      const smallProblems = watchProblems(small);
      await small.goto(`${url}/#/shapes/${id}`, { waitUntil: 'load' });
      await small.waitForFunction((n) => (document.querySelector('#canvas').dataset.shown || '').startsWith(`shape/${n}@`), id, { timeout: 60000 * slowdown });
      for (const selector of ['#canvas', '#query', '#alpha']) {
        const box = await small.locator(selector).boundingBox();
        if (!box || !(await small.locator(selector).isVisible())) throw new Error(`${label}: ${selector} is not visible`);
        if (box.x < 0 || box.x + box.width > width + 0.5) throw new Error(`${label}: ${selector} leaves the screen: ${JSON.stringify(box)}`);
      }
      const wide = await small.evaluate(() => document.documentElement.scrollWidth);
      if (wide > width) throw new Error(`${label}: the page is ${wide} px wide on a ${width} px screen`);
      // Usable: the slider moves the view, the search box searches.
      await small.locator('#alpha').fill('1');
      await small.waitForFunction((n) => document.querySelector('#canvas').dataset.shown === `shape/${n}@1`, id, { timeout: 60000 * slowdown });
      await small.fill('#query', 'a bent cylinder');
      await small.press('#query', 'Enter');
      await small.waitForFunction(() => document.querySelector('#status').textContent.includes('linguistic search'));
      await small.evaluate(() => window.scrollTo(0, 0));
      const png = await small.screenshot({ path: path.join(out, `studio-${label}.png`) });
      const ink = await inkShare(small, png);
      inks.push(`${label} ${ink.toFixed(4)}`);
      if (ink < 0.01) throw new Error(`the ${label} screenshot is blank`);
      problems.push(...smallProblems);
      await small.close();
    });
  }

  console.log(`studio build steps: ${times.join('; ')}`);
  console.log(`ink share: ${inks.join(', ')}`);
  if (problems.length) throw new Error(problems.join('\n'));
  console.log('studio build: ok');
}

runPageTest(fsdb, source, webDir, main);
