// Build a shape: a CSG tree made in the Structure panel, which is its editor. Parts are
// added from words ("a big box": an inline part with `text`), from the catalogue (a stored part,
// referenced by name) or new (a unit sphere); each operation node's operation is chosen
// (union, intersection, difference) and operations nest; a part is placed against an earlier one
// in words ("about 3 units right of big-box": the leaf's `transform.place`, docs/api.md
// "Placements from words"). The view previews the unsaved tree through POST /mesh (coarse, then
// full); saving stores it (POST /shapes) and opens it.
import { api, apiBytes } from './api.js';

const $ = (id) => document.getElementById(id);
const OPS = ['union', 'intersection', 'difference'];

// A name for a part made from words: its words without the article, as a slug ("big-box").
export function slug(text) {
  return text.toLowerCase().replace(/^\s*(an?|the)\s+/, '').replace(/[^a-z0-9]+/g, '-').replace(/^-|-$/g, '') || 'part';
}

// The API's tree for the editor's one: operations keep their children, leaves become part leaves
// (inline from words or new, or a stored part's name) with their placement.
export function treeDocument(node) {
  if (node.op) return { op: node.op, children: node.children.map(treeDocument) };
  const part = node.source === 'catalogue' ? node.part
    : node.source === 'words' ? { name: node.name, text: node.text } : { name: node.name, params: { a1: 1 } };
  const leaf = { part };
  if (node.place) {
    const place = { relative_to: node.place.relative_to, direction: node.place.direction };
    if (node.place.distance) place.distance = node.place.distance;
    leaf.transform = { place };
  }
  return leaf;
}

// Why the tree cannot be evaluated yet (an operation needs two operands), or null.
export function incomplete(node) {
  if (!node.op) return null;
  if (node.children.length < 2) return `the ${node.op} needs at least two parts (it has ${node.children.length})`;
  for (const child of node.children) {
    const why = incomplete(child);
    if (why) return why;
  }
  return null;
}

// The leaves in pre-order: a part may be placed against the ones before it.
function leaves(node, into = []) {
  if (node.op) for (const child of node.children) leaves(child, into);
  else into.push(node);
  return into;
}

export function setupBuilder(view) {
  let root = { op: 'union', children: [] };
  let target = root;  // the operation new parts and operations go into
  let edits = 0;
  let vocabulary = null;  // directions for the placement's list (GET /vocabulary)

  function builderStatus(text, error = false) {
    $('builder-status').textContent = text;
    $('builder-status').style.color = error ? '#b00' : '';
  }

  function uniqueName(base) {
    const taken = new Set(leaves(root).map((l) => l.name));
    let name = base;
    for (let k = 2; taken.has(name); k++) name = `${base}-${k}`;
    return name;
  }

  function select(options, value, attrs) {
    const s = Object.assign(document.createElement('select'), attrs);
    for (const o of options) s.append(Object.assign(document.createElement('option'), { value: o, textContent: o }));
    if (value !== undefined) s.value = value;
    return s;
  }

  function button(text, action, onClick) {
    const b = Object.assign(document.createElement('button'), { type: 'button', textContent: text });
    b.dataset.action = action;
    b.addEventListener('click', onClick);
    return b;
  }

  function remove(node, parent) {
    parent.children.splice(parent.children.indexOf(node), 1);
    // Placements against a removed part have nothing to hold on to.
    const names = new Set(leaves(root).map((l) => l.name));
    for (const l of leaves(root)) if (l.place && !names.has(l.place.relative_to)) l.place = null;
    if (!leaves(root).length && !root.children.length) target = root;
    if (node === target || (node.op && !contains(root, target))) target = root;
    changed();
  }

  function contains(node, wanted) {
    return node === wanted || (node.op && node.children.some((c) => contains(c, wanted)));
  }

  // "[distance] units [direction] of [an earlier part]": the placement as the words say it.
  function placement(leaf) {
    const span = document.createElement('span');
    span.className = 'placement';
    const earlier = leaves(root).slice(0, leaves(root).indexOf(leaf)).map((l) => l.name);
    const place = leaf.place;
    const distance = Object.assign(document.createElement('input'), { value: place.distance, placeholder: 'about 3', size: 9 });
    distance.dataset.field = 'distance';
    distance.title = 'a fuzzy distance in words or a number ("about 3", "between 2 and 4", near); empty: touching';
    const directions = vocabulary ? [...vocabulary.primary, ...vocabulary.secondary, ...vocabulary.phrases] : ['right'];
    const direction = select(directions, place.direction, {});
    direction.dataset.field = 'direction';
    const against = select(earlier, place.relative_to, {});
    against.dataset.field = 'relative_to';
    const update = () => {
      Object.assign(place, { distance: distance.value.trim(), direction: direction.value, relative_to: against.value });
      changed();
    };
    distance.addEventListener('change', update);
    direction.addEventListener('change', update);
    against.addEventListener('change', update);
    span.append(' placed ', distance, ' units ', direction, ' of ', against);
    return span;
  }

  function nodeItem(node, parent) {
    const li = document.createElement('li');
    if (node.op) {
      li.dataset.node = 'op';
      li.classList.toggle('target', node === target);
      const op = select(OPS, node.op, { className: 'op' });
      op.dataset.action = 'set-op';
      op.addEventListener('change', () => { node.op = op.value; changed(); });
      const into = button('add here', 'target', () => { target = node; render(); });
      into.title = 'new parts and operations go into this operation';
      li.append(op, ' ', into);
      if (parent) li.append(' ', button('×', 'remove-node', () => remove(node, parent)));
      const ul = document.createElement('ul');
      for (const child of node.children) ul.append(nodeItem(child, node));
      li.append(ul);
      return li;
    }
    li.dataset.node = 'part';
    li.dataset.name = node.name;
    const what = node.source === 'words' ? `“${node.text}”` : node.source === 'catalogue' ? 'from the catalogue' : 'a unit sphere';
    li.append('part ', Object.assign(document.createElement('b'), { textContent: node.name }), ` ${what} `);
    const isFirst = leaves(root)[0] === node;
    if (!isFirst) {
      const place = button(node.place ? 'unplace' : 'place…', 'place', () => {
        node.place = node.place ? null
          : { relative_to: leaves(root)[leaves(root).indexOf(node) - 1].name, direction: 'right', distance: '' };
        changed();
      });
      place.title = 'place it against an earlier part, in words';
      li.append(place);
    }
    li.append(' ', button('×', 'remove-node', () => remove(node, parent)));
    if (node.place) li.append(placement(node));
    return li;
  }

  function render() {
    const ul = document.createElement('ul');
    ul.className = 'builder-tree';
    ul.append(nodeItem(root, null));
    $('tree').replaceChildren(ul);
  }

  // The unsaved tree in the view: a coarse mesh (24 voxels across), then the full one (48).
  async function draw() {
    const why = incomplete(root);
    if (why) {
      view.status(`add parts: ${why}`);
      return;
    }
    const which = edits;
    const alpha = view.alpha();
    const doc = { kind: 'shape', tree: treeDocument(root) };
    view.busy(true);
    try {
      for (const resolution of [24, 48]) {
        view.status(`computing the new shape at α = ${alpha.toFixed(2)} (${resolution === 24 ? 'coarse' : 'full'})…`);
        const model = await view.fetchDocumentScene(doc, alpha, resolution);
        if (which !== edits) return;
        view.showModel(model);
      }
      view.status(`new shape, not saved: α = ${alpha.toFixed(2)}`);
      $('canvas').dataset.shown = `draft:${which}@${alpha}`;
      view.chart(doc);
    } catch (e) {
      if (which === edits) builderStatus(e.message, true);
    } finally {
      if (which === edits) view.busy(false);
    }
  }

  // The tree changed: drawn again in the panel and in the view.
  function changed() {
    edits += 1;
    render();
    builderStatus('');
    view.refit();
    draw().catch((e) => builderStatus(e.message, true));
  }

  async function addPart() {
    const source = $('add-source').value;
    const text = $('add-text').value.trim();
    if (source !== 'new' && !text) {
      builderStatus(source === 'words' ? 'say the part in words: "a big box"' : 'name a part of the catalogue', true);
      return;
    }
    let leaf;
    if (source === 'catalogue') {
      // The catalogue's part by its name (the tree references it; a new version of it changes the shape).
      const page = await api(`/parts?name=${encodeURIComponent(text)}`);
      if (!page.items.length) {
        builderStatus(`no part named “${text}” in the catalogue`, true);
        return;
      }
      if (leaves(root).some((l) => l.name === text)) {
        builderStatus(`${text} is in the tree already`, true);
        return;
      }
      leaf = { source, part: text, name: text };
    } else if (source === 'words') {
      // The words are read before the part joins the tree (a mesh of 8 voxels: some 60 ms), so an
      // unknown word is said here, with its closest words, not by every preview after.
      const body = JSON.stringify({ shape: { kind: 'part', text }, alpha: 0.5, resolution: 8, format: 'glb' });
      try {
        await apiBytes('/mesh', { method: 'POST', body });
      } catch (e) {
        builderStatus(e.message, true);
        return;
      }
      leaf = { source, text, name: uniqueName(slug(text)) };
    } else {
      leaf = { source, name: uniqueName('sphere') };
    }
    leaf.place = null;
    target.children.push(leaf);
    $('add-text').value = '';
    changed();
  }

  function addGroup() {
    const group = { op: 'difference', children: [] };
    target.children.push(group);
    target = group;
    changed();
  }

  async function save() {
    const why = incomplete(root);
    const name = $('shape-name').value.trim();
    if (why || !name) {
      builderStatus(why || 'name the shape to save it', true);
      return;
    }
    try {
      const created = await api('/shapes', { method: 'POST', body: JSON.stringify({ kind: 'shape', name, tree: treeDocument(root) }) });
      await view.open('shape', created.id);
    } catch (e) {
      builderStatus(e.message, true);
    }
  }

  async function start() {
    root = { op: 'union', children: [] };
    target = root;
    edits += 1;
    view.showDraft('a new shape (not saved)');
    render();
    builderStatus('');
    view.status('add parts: from words, from the catalogue, or new');
    if (!vocabulary) {
      const v = await api('/vocabulary');
      const words = (x) => (Array.isArray(x) ? x : Object.keys(x));
      vocabulary = { primary: words(v.directions.primary), secondary: words(v.directions.secondary), phrases: words(v.directions.phrases) };
    }
    // The catalogue's part names, offered as the user types (a first page: the list filters as typed).
    const parts = await api('/parts?limit=1000');
    $('catalogue-parts').replaceChildren(...parts.items.map((p) => Object.assign(document.createElement('option'), { value: p.name })));
    view.own(draw);
  }

  $('new-shape').addEventListener('click', () => start().catch((e) => builderStatus(e.message, true)));
  $('add-part-form').addEventListener('submit', (event) => {
    event.preventDefault();
    addPart().catch((e) => builderStatus(e.message, true));
  });
  $('add-source').addEventListener('change', () => {
    const source = $('add-source').value;
    $('add-text').disabled = source === 'new';
    $('add-text').placeholder = source === 'words' ? 'a big box' : source === 'catalogue' ? 'a part’s name' : '';
    $('add-text').setAttribute('list', source === 'catalogue' ? 'catalogue-parts' : '');
  });
  $('add-group').addEventListener('click', addGroup);
  $('save-shape').addEventListener('click', () => save());

  return {
    // A stored object opened: the builder's tree is left (it is not saved).
    opened() {},
  };
}
