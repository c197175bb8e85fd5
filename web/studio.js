// The fsdb studio: one search box over POST /query, ranked thumbnails, a 3D view of lower(α)
// solid and upper(α) translucent (GLB from GET /{kind}s/{id}/mesh?format=glb) with an α slider,
// the fuzzy volume over α, the CSG tree with each part's parameters, membership at a clicked
// point, browsing and search with paging, parts from words, a JSON Lines import with progress and
// every failed line, downloads (GLB, OBJ, STL at α; .vdb), addresses of objects (#/shapes/ID) and
// a bearer token for servers run with --token; and the design tools of web/part_editor.js (edit a
// part's fuzzy values with a live preview, save a version), web/versions.js (history, compare)
// and web/members.js (the family's crisp members); a shape built in the Structure panel
// (web/modules/builder.js); curves with their α levels or fair candidates (one chosen and stored)
// and surfaces with their control nets (web/modules/curves.js).
import * as THREE from 'three';
import { OrbitControls } from 'three/addons/controls/OrbitControls.js';
import { GLTFLoader } from 'three/addons/loaders/GLTFLoader.js';
import { api, apiBytes, authHeaders } from './modules/api.js';
import { fitCamera, litScene } from './modules/scene.js';
import { fuzzyText, setupEditor } from './modules/part_editor.js';
import { setupVersions } from './modules/versions.js';
import { setupMembers } from './modules/members.js';
import { setupBuilder } from './modules/builder.js';
import { setupCurves } from './modules/curves.js';

const $ = (id) => document.getElementById(id);

function status(text, error = false) {
  $('status').textContent = text;
  $('status').style.color = error ? '#b00' : '';
}

// ---- results ------------------------------------------------------------------------------
let nextPage = null;  // () => Promise, for "More"

function card(item) {
  const li = document.createElement('li');
  li.dataset.kind = item.kind;
  li.dataset.id = item.id;
  const picture = item.kind === 'curve'
    ? Object.assign(document.createElement('img'), { src: `/curves/${item.id}/svg`, className: 'svg' })
    : item.kind === 'surface'
      ? Object.assign(document.createElement('div'), { className: 'svg', textContent: 'surface' })
      : Object.assign(document.createElement('img'), { src: `/${item.kind}s/${item.id}/thumbnail.png`, loading: 'lazy' });
  picture.alt = item.name;
  li.append(picture);
  const name = document.createElement('div');
  name.className = 'name';
  name.textContent = item.name || `#${item.id}`;
  if (item.score !== undefined) {
    const score = document.createElement('span');
    score.className = 'score';
    score.textContent = item.score.toFixed(3);
    name.append(score);
  }
  li.append(name);
  if (item.explain && item.explain.length) {
    const list = document.createElement('ul');
    list.className = 'explain';
    for (const e of item.explain) {
      const row = document.createElement('li');
      row.textContent = `${e.text}: ${e.score.toFixed(2)}`;
      list.append(row);
    }
    li.append(list);
  }
  li.addEventListener('click', () => open(item.kind, item.id, li));
  return li;
}

// The name filter hides the cards whose name does not contain its text (the shown pages).
function applyFilter() {
  const text = $('filter').value.trim().toLowerCase();
  for (const li of $('results').children)
    li.hidden = text !== '' && !li.querySelector('.name').textContent.toLowerCase().includes(text);
}
$('filter').addEventListener('input', applyFilter);

function show(items, append = false) {
  if (!append) $('results').replaceChildren();
  for (const item of items) $('results').append(card(item));
  applyFilter();
}

// How the text was read, shown above its results: the grammar's words (`read_as`); the words
// routed to known ones (an inflection, a WordNet link) with their discount; the words not
// understood, each closest word a link that puts it in the text and searches again; the text
// searched instead (`read_text`); when nothing met every condition, that the results are the
// closest partial matches; and, when the search left out words it could have corrected, the
// corrected text as one link.
function link(text, action, onClick) {
  const a = Object.assign(document.createElement('a'), { href: '#', textContent: text });
  a.dataset.action = action;
  a.addEventListener('click', (event) => {
    event.preventDefault();
    onClick();
  });
  return a;
}

function searchFor(text) {
  $('query').value = text;
  search(text);
}

function showReading(answer, text) {
  const p = $('read-as');
  p.replaceChildren();
  const part = (...nodes) => p.append(...(p.childNodes.length ? [' · '] : []), ...nodes);
  if (answer.parsed && answer.parsed.read_as) part(`Read as: ${answer.parsed.read_as}`);
  for (const r of answer.routed || []) {
    const span = Object.assign(document.createElement('span'), { className: 'routed' });
    span.textContent = `read “${r.word}” as “${r.became}” (${r.why}${r.discount < 1 ? `, scores × ${r.discount}` : ''})`;
    part(span);
  }
  if (answer.ignored && answer.ignored.length) {
    const words = [];
    for (const w of answer.ignored) {
      if (words.length) words.push(', ');
      words.push(`“${w.word}”`);
      if (!w.did_you_mean.length) continue;
      words.push(' (');
      w.did_you_mean.forEach((better, k) => {
        if (k) words.push(', ');
        // The one word replaced where it stands in the text.
        words.push(link(better, 'correct-word', () => searchFor(`${text.slice(0, w.at)}${better}${text.slice(w.at + w.word.length)}`)));
      });
      words.push('?)');
    }
    part(`Searched for “${answer.read_text}”; not understood: `, ...words);
  } else if (answer.read_text && answer.read_text !== text) {
    part(`Searched for “${answer.read_text}”`);
  }
  if (answer.partial) part('nothing meets every condition: the closest partial matches');
  if (answer.did_you_mean) p.append(' · Did you mean ', link(answer.did_you_mean, 'did-you-mean', () => searchFor(answer.did_you_mean)), '?');
}

// The text of the last search, which a new threshold runs again.
let lastSearch = null;

// A search shows 12 results; "More" asks again for 12 more (the ranking is the same, so the
// first ones stay where they were).
async function search(text, limit = 12) {
  status('Searching…');
  $('more').hidden = true;
  try {
    // The least score (the threshold control); 0 asks for every result.
    const threshold = Number($('threshold').value);
    const answer = await api('/query', { method: 'POST', body: JSON.stringify({ text, limit, ...(threshold > 0 ? { threshold } : {}) }) });
    lastSearch = text;
    showReading(answer, text);
    const items = answer.results.map((r) => ({
      ...r,
      kind: r.kind || 'shape',
      explain: r.explain || [
        { text: 'components', score: r.components }, { text: 'transforms', score: r.transforms },
        { text: 'structure', score: r.structure },
        ...(r.relations || []).map((x) => ({ text: `${x.subject} ${x.text} ${x.object}`, score: x.score })),
      ],
    }));
    show(items);
    status(`${items.length} result${items.length === 1 ? '' : 's'}${threshold > 0 ? ` scoring at least ${threshold.toFixed(2)}` : ''} (${answer.search} search, ${answer.millis.toFixed(1)} ms)`);
    // A full page may have more behind it (at most 1000: the search's limit).
    $('more').hidden = items.length < limit || limit >= 1000;
    nextPage = () => search(text, Math.min(limit + 12, 1000));
  } catch (e) {
    $('results').replaceChildren();
    $('read-as').textContent = '';
    status(e.message, true);
  }
}

async function browse(kind, after = null, append = false) {
  try {
    const page = await api(`/${kind}?limit=24${after === null ? '' : `&after=${after}`}`);
    $('read-as').textContent = '';
    show(page.items.map((o) => ({ id: o.id, name: o.name, kind: o.kind })), append);
    status(`${kind}: ${$('results').children.length} shown`);
    $('more').hidden = page.next_after === null;
    nextPage = () => browse(kind, page.next_after, true);
  } catch (e) {
    status(e.message, true);
  }
}

// ---- the 3D view ----------------------------------------------------------------------------
const renderer = new THREE.WebGLRenderer({ canvas: $('canvas'), antialias: true, preserveDrawingBuffer: true });
renderer.setPixelRatio(window.devicePixelRatio);
const scene = litScene();
const camera = new THREE.PerspectiveCamera(40, 1, 0.01, 1000);
const controls = new OrbitControls(camera, renderer.domElement);
const materials = {
  lower: new THREE.MeshStandardMaterial({ color: 0x4673cd, roughness: 0.6 }),
  upper: new THREE.MeshStandardMaterial({ color: 0xeb8232, roughness: 0.6, transparent: true, opacity: 0.35, depthWrite: false }),
};
let model = null;
let current = null;  // {kind, id, name, document}
let fitted = false;

// Drawn on demand (a move of the camera, a new mesh, a resize), not in a loop: an idle page
// costs no CPU, which a software-rendered WebGL would otherwise burn.
function render() {
  renderer.render(scene, camera);
}
controls.addEventListener('change', render);

function resize() {
  const box = $('canvas-box');
  renderer.setSize(box.clientWidth, box.clientHeight, false);
  camera.aspect = box.clientWidth / Math.max(1, box.clientHeight);
  camera.updateProjectionMatrix();
  render();
}
window.addEventListener('resize', resize);

// The view at α: a coarse mesh first (24 voxels across, a fraction of the time), then the full
// one (64), so that a slow part (many fuzzy values, a part just made from words) never leaves the
// view blank; #view-status says what is on screen. A newer request (another α or object) makes
// older answers stale: they are dropped, not shown.
let meshRequest = 0;
async function sceneFromGlb(bytes) {
  return (await new GLTFLoader().parseAsync(bytes, '')).scene;
}

async function fetchScene(kind, id, alpha, resolution) {
  return sceneFromGlb(await apiBytes(`/${kind}s/${id}/mesh?format=glb&alpha=${alpha}&resolution=${resolution}`));
}

// The mesh of a document that need not be stored (an edited part, an older version, a member):
// POST /mesh answers the bytes GET /{kind}s/{id}/mesh gives for a stored one.
async function fetchDocumentScene(doc, alpha, resolution) {
  const body = JSON.stringify({ shape: doc, alpha, resolution, format: 'glb' });
  return sceneFromGlb(await apiBytes('/mesh', { method: 'POST', body }));
}

// Puts `next` in the view in place of the model shown. Meshes named lower and upper (the GLB's)
// take the view's materials unless `keepMaterials` (a comparison tints its own).
function showModel(next, keepMaterials = false) {
  if (model) scene.remove(model);
  model = next;
  model.traverse((o) => {
    if (o.isMesh && !keepMaterials) {
      o.material = materials[o.name] || materials.lower;
      o.renderOrder = o.name === 'upper' ? 1 : 0;
    }
  });
  scene.add(model);
  if (!fitted) {
    controls.target.copy(fitCamera(camera, model));
    controls.update();
    fitted = true;
  }
  render();
}

// The download links of the view: meshes of lower and upper at the slider's α, and the grids.
function updateExports() {
  if (!current) return;
  const alpha = Number($('alpha').value);
  const base = `/${current.kind}s/${current.id}`;
  for (const a of document.querySelectorAll('#exports a')) {
    const format = a.dataset.action.replace('export-', '');
    a.href = format === 'vdb' ? `${base}/grid.vdb`
      : `${base}/mesh?format=${format}&alpha=${alpha}${a.dataset.bound ? `&bound=${a.dataset.bound}` : ''}`;
  }
}

async function loadMesh() {
  const alpha = Number($('alpha').value);
  const { kind, id } = current;
  updateExports();
  const request = ++meshRequest;
  const stale = () => request !== meshRequest || !current || current.id !== id;
  const started = performance.now();
  $('view-status').textContent = `computing α = ${alpha.toFixed(2)}…`;
  const coarse = await fetchScene(kind, id, alpha, 24);
  if (stale()) return;
  showModel(coarse);
  $('canvas').dataset.coarse = `${kind}/${id}@${alpha}`;
  $('view-status').textContent = `coarse preview at α = ${alpha.toFixed(2)}; refining…`;
  const fine = await fetchScene(kind, id, alpha, 64);
  if (stale()) return;
  showModel(fine);
  const seconds = ((performance.now() - started) / 1000).toFixed(1);
  $('view-status').textContent = `α = ${alpha.toFixed(2)} (${seconds} s)`;
  $('canvas').dataset.shown = `${kind}/${id}@${alpha}`;  // for the page test: what the view shows
}

// What the view shows decides what a new α redraws: the stored object (loadMesh), or what a
// design tool put there (an edited part, a comparison, a member), which sets `redraw` through
// view.own and gives it back when the object is opened again.
let redraw = loadMesh;

let alphaTimer = null;
$('alpha').addEventListener('input', () => {
  $('alpha-value').textContent = Number($('alpha').value).toFixed(2);
  clearTimeout(alphaTimer);
  alphaTimer = setTimeout(() => redraw().catch((e) => status(e.message, true)), 120);
});

$('canvas').addEventListener('click', async (event) => {
  if (!model || !current) return;
  const rect = $('canvas').getBoundingClientRect();
  const pointer = new THREE.Vector2(((event.clientX - rect.left) / rect.width) * 2 - 1,
    -((event.clientY - rect.top) / rect.height) * 2 + 1);
  const ray = new THREE.Raycaster();
  ray.setFromCamera(pointer, camera);
  const hit = ray.intersectObject(model, true)[0];
  if (!hit) return;
  const p = hit.point;
  const where = `(${p.x.toFixed(2)}, ${p.y.toFixed(2)}, ${p.z.toFixed(2)})`;
  try {
    const m = await api(`/${current.kind}s/${current.id}/membership?x=${p.x}&y=${p.y}&z=${p.z}`);
    $('membership').textContent = `${where} on ${hit.object.name}: possibly inside up to α = ${m.upper.toFixed(2)}, ` +
      (m.lower_from !== null ? `necessarily inside from α = ${m.lower_from.toFixed(2)}` : 'never necessarily inside') +
      (m.exact ? '' : ' (bounds only: a search ran out of its budget)');
  } catch (e) {
    $('membership').textContent = e.message;
  }
});

// ---- fuzzy volume and structure -------------------------------------------------------------
// The fuzzy volume over α of the object shown, or of `draft` (a document not stored).
async function chart(draft = null) {
  const alphas = Array.from({ length: 11 }, (_, i) => i / 10);
  const request = { resolution: 32, alphas };
  const answer = !draft && current.kind === 'shape'
    ? await api(`/shapes/${current.id}/evaluate`, { method: 'POST', body: JSON.stringify(request) })
    : await api('/evaluate', { method: 'POST', body: JSON.stringify({ ...request, shape: draft || current.document }) });
  const levels = answer.alphas;
  const top = Math.max(...levels.map((l) => l.upper_volume), 1e-12);
  const x = (a) => 40 + a * 260, y = (v) => 160 - (v / top) * 140;
  const line = (key) => levels.map((l, i) => `${i ? 'L' : 'M'}${x(l.alpha).toFixed(1)},${y(l[key]).toFixed(1)}`).join(' ');
  $('chart').innerHTML = `
    <path d="M40,20 L40,160 L300,160" fill="none" stroke="#99a"/>
    <text x="4" y="24" font-size="10">${top.toPrecision(3)}</text><text x="20" y="163" font-size="10">0</text>
    <text x="36" y="174" font-size="10">α = 0</text><text x="290" y="174" font-size="10">1</text>
    <path d="${line('upper_volume')}" fill="none" stroke="#eb8232" stroke-width="2"/>
    <path d="${line('lower_volume')}" fill="none" stroke="#4673cd" stroke-width="2"/>
    <text x="200" y="34" font-size="10" fill="#eb8232">vol upper(α)</text>
    <text x="200" y="48" font-size="10" fill="#4673cd">vol lower(α)</text>`;
}

function treeNode(node) {
  const li = document.createElement('li');
  if (node.op) {
    li.innerHTML = `<span class="op">${node.op}</span>`;
    const ul = document.createElement('ul');
    for (const child of node.children || []) ul.append(treeNode(child));
    li.append(ul);
  } else if (node.ref !== undefined) {
    li.textContent = `shape ${JSON.stringify(node.ref)}`;
  } else {
    const part = node.part;
    const params = typeof part === 'object' ? part.params || {} : null;
    li.innerHTML = `part <b>${typeof part === 'object' ? part.name || part.text || 'inline' : part}</b>`;
    const p = document.createElement('div');
    p.className = 'params';
    const paramText = (ps) => Object.entries(ps).map(([k, v]) => `${k} = ${fuzzyText(v)}`).join(' · ');
    if (params) {
      p.textContent = paramText(params);
    } else {
      // A stored part named by the tree: its parameters from the store.
      api(`/parts?name=${encodeURIComponent(part)}`).then((page) => {
        const doc = page.items.length ? page.items[page.items.length - 1].document : null;
        p.textContent = doc ? (doc.params ? paramText(doc.params) : doc.text || '') : '';
      }).catch(() => {});
    }
    li.append(p);
    if (node.transform) {
      const t = document.createElement('div');
      t.className = 'params';
      t.textContent = `transform ${JSON.stringify(node.transform)}`;
      li.append(t);
    }
  }
  return li;
}

function tree() {
  const doc = current.document;
  const ul = document.createElement('ul');
  ul.append(doc.kind === 'part' ? treeNode({ part: doc }) : doc.tree ? treeNode(doc.tree) : Object.assign(document.createElement('li'), { textContent: doc.csg }));
  $('tree').replaceChildren(ul);
}

// A part or shape opens with its mesh, structure and fuzzy volume; a curve or surface in its own
// mode (web/modules/curves.js draws it).
async function open(kind, id, li) {
  for (const other of document.querySelectorAll('#results > li.selected')) other.classList.remove('selected');
  if (li) li.classList.add('selected');
  try {
    const stored = await api(`/${kind}s/${id}`);
    current = { kind, id, name: stored.name, document: stored.document, version: stored.version };
    redraw = loadMesh;
    // The design tools load what they need of the object while the view draws it.
    const toolsReady = Promise.all(tools.map((tool) => tool.opened(current)));
    // The object's address (/#/parts/ID, /#/shapes/ID): a reload or a shared link opens it again.
    if (location.hash !== `#/${kind}s/${id}`) history.replaceState(null, '', `${location.pathname}${location.search}#/${kind}s/${id}`);
    $('view').hidden = false;
    $('view').dataset.mode = kind === 'curve' || kind === 'surface' ? kind : 'object';
    $('title').textContent = `${kind} ${stored.name} (#${id}, version ${stored.version})`;
    resize();
    fitted = false;
    if (kind === 'curve' || kind === 'surface') {
      await toolsReady;
      return;
    }
    await loadMesh();
    tree();
    await chart();
    await toolsReady;
  } catch (e) {
    status(e.message, true);
  }
}

// ---- forms ----------------------------------------------------------------------------------
$('search').addEventListener('submit', (event) => {
  event.preventDefault();
  const text = $('query').value.trim();
  if (text) search(text);
});
for (const button of document.querySelectorAll('[data-browse]'))
  button.addEventListener('click', () => browse(button.dataset.browse));
$('more').addEventListener('click', () => nextPage && nextPage());
$('threshold').addEventListener('input', () => {
  $('threshold-value').textContent = Number($('threshold').value).toFixed(2);
});
$('threshold').addEventListener('change', () => {
  if (lastSearch) search(lastSearch);
});

$('create').addEventListener('submit', async (event) => {
  event.preventDefault();
  const text = $('words').value.trim();
  if (!text) return;
  try {
    const name = `${text.replace(/[^a-z0-9]+/gi, '-').replace(/^-|-$/g, '').toLowerCase()}-${Date.now().toString(36)}`;
    const created = await api('/parts', { method: 'POST', body: JSON.stringify({ kind: 'part', name, text }) });
    show([{ id: created.id, name, kind: 'part' }]);
    status(`created part ${name}`);
    await open('part', created.id, $('results').firstChild);
  } catch (e) {
    status(e.message, true);
  }
});

$('file').addEventListener('change', () => {
  const file = $('file').files[0];
  if (!file) return;
  const xhr = new XMLHttpRequest();
  $('progress').hidden = false;
  xhr.upload.onprogress = (e) => { if (e.lengthComputable) $('progress').value = e.loaded / e.total; };
  $('import-errors').replaceChildren();
  xhr.onload = () => {
    $('progress').value = 1;
    const body = JSON.parse(xhr.responseText || '{}');
    $('import-status').textContent = xhr.status === 200
      ? `imported ${body.imported}, failed ${body.failed}${body.errors_truncated ? ' (the first errors listed)' : ''}`
      : (body.error ? body.error.message : `HTTP ${xhr.status}`);
    // Every failed line, with its number and what was wrong, and where in the line.
    for (const e of (xhr.status === 200 && body.errors) || []) {
      const row = document.createElement('li');
      row.textContent = `line ${e.line}: ${e.error.message}${e.error.path ? ` (at ${e.error.path})` : ''}`;
      $('import-errors').append(row);
    }
    if (xhr.status === 200 && body.imported) browse('parts');  // the list shows what came in
  };
  xhr.onerror = () => { $('import-status').textContent = 'the upload failed'; };
  xhr.open('POST', '/parts/bulk?mode=create');
  xhr.setRequestHeader('Content-Type', 'application/x-ndjson');
  for (const [name, value] of Object.entries(authHeaders())) xhr.setRequestHeader(name, value);
  xhr.send(file);
});

$('token').value = sessionStorage.getItem('fsdb-token') || '';
$('token').addEventListener('input', () => {
  const token = $('token').value.trim();
  if (token) sessionStorage.setItem('fsdb-token', token);
  else sessionStorage.removeItem('fsdb-token');
});
$('token-form').addEventListener('submit', (event) => event.preventDefault());

// ---- design tools ---------------------------------------------------------------------------
// What the tools may do with the view. A tool that draws there owns `redraw` (a new α asks it).
const view = {
  alpha: () => Number($('alpha').value),
  current: () => current,
  fetchDocumentScene,
  showModel,
  render,
  chart: (doc) => chart(doc).catch((e) => status(e.message, true)),
  open: (kind, id) => open(kind, id, null),
  // The next model shown places the camera again (the object's size changed).
  refit() {
    fitted = false;
  },
  // The view without a stored object (a shape being built): `mode` shows its controls only.
  showDraft(title, mode = 'draft') {
    current = null;
    for (const other of document.querySelectorAll('#results > li.selected')) other.classList.remove('selected');
    if (location.hash) history.replaceState(null, '', `${location.pathname}${location.search}`);
    if (model) scene.remove(model);
    model = null;
    delete $('canvas').dataset.shown;
    $('view').hidden = false;
    $('view').dataset.mode = mode;
    $('title').textContent = title;
    $('chart').replaceChildren();
    resize();
    fitted = false;
  },
  // A stored object opened again (after a save, or a reload on a conflict).
  reopen: () => open(current.kind, current.id, null),
  own(redrawFn) {
    redraw = redrawFn;
  },
  status(text) {
    $('view-status').textContent = text;
  },
  // "computing…" over the view while a request is in flight: the last picture stays under it.
  busy(on) {
    $('canvas-box').classList.toggle('busy', on);
  },
};
const editor = setupEditor(view);
const tools = [editor, setupVersions(view, editor), setupMembers(view), setupBuilder(view), setupCurves(view)];

// An object in the address (#/parts/ID, #/shapes/ID, #/curves/ID, #/surfaces/ID) opens in the view.
function openFromAddress() {
  const m = /^#\/(part|shape|curve|surface)s\/(\d+)$/.exec(location.hash);
  if (m && !(current && current.kind === m[1] && current.id === Number(m[2]))) open(m[1], Number(m[2]), null);
}
window.addEventListener('hashchange', openFromAddress);

// A query in the address (?q=...) runs at once; otherwise the shapes are listed.
const initial = new URLSearchParams(location.search).get('q');
if (initial) {
  $('query').value = initial;
  search(initial);
} else {
  browse('shapes');
}
openFromAddress();
