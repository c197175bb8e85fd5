// An object's versions (GET /{kind}s/{id}?version=N): the history list, where any version opens
// in the view and, for a part, in the editor; and a comparison of two versions: their values side
// by side (the differing ones marked) and both envelopes overlaid in the view, version A blue and
// version B red. Older versions have no stored mesh route, so every picture here comes from POST
// /mesh of the version's document.
import * as THREE from 'three';
import { api } from './api.js';
import { PART_VALUES, fuzzyText, valueAt } from './part_editor.js';

const $ = (id) => document.getElementById(id);

// At most this many versions are listed, the newest (each is one GET); the list says how many
// older ones it leaves out.
const LISTED_VERSIONS = 20;

// Both versions' meshes in one group: each version's lower(α) and upper(α) in its colour, upper
// fainter, so where the two envelopes differ shows as blue or red.
function tinted(scene, colour) {
  scene.traverse((o) => {
    if (!o.isMesh) return;
    const upper = o.name === 'upper';
    o.material = new THREE.MeshStandardMaterial({ color: colour, roughness: 0.6, transparent: true,
      opacity: upper ? 0.25 : 0.6, depthWrite: !upper });
    o.renderOrder = upper ? 2 : 1;
  });
  return scene;
}

export function setupVersions(view, editor) {
  let object = null;  // {kind, id, latest}
  const documents = new Map();  // version -> stored object

  async function version(n) {
    if (!documents.has(n)) documents.set(n, await api(`/${object.kind}s/${object.id}?version=${n}`));
    return documents.get(n);
  }

  async function showVersion(n) {
    const stored = await version(n);
    const draw = async () => {
      view.busy(true);
      view.status(`computing version ${n}…`);
      try {
        view.showModel(await view.fetchDocumentScene(stored.document, view.alpha(), 48));
        view.status(`version ${n} of ${object.latest}, α = ${view.alpha().toFixed(2)}`);
        $('canvas').dataset.shown = `version:${n}@${view.alpha()}`;
      } finally {
        view.busy(false);
      }
    };
    view.own(draw);
    $('title').textContent = `${object.kind} ${stored.name} (#${object.id}, version ${n} of ${object.latest})`;
    if (object.kind === 'part') await editor.loadVersion(object.id, n);
    await draw();
  }

  async function history() {
    const newest = object.latest;
    const numbers = [];
    for (let n = newest; n >= 1 && numbers.length < LISTED_VERSIONS; n--) numbers.push(n);
    const rows = await Promise.all(numbers.map(version));
    const list = $('version-list');
    list.replaceChildren();
    for (const stored of rows) {
      const tr = document.createElement('tr');
      tr.dataset.version = stored.version;
      const open = Object.assign(document.createElement('button'), { type: 'button', textContent: `version ${stored.version}` });
      open.dataset.action = 'open-version';
      open.addEventListener('click', () => showVersion(stored.version).catch((e) => view.status(e.message)));
      const pick = (side) => {
        const radio = Object.assign(document.createElement('input'), { type: 'radio', name: `compare-${side}`, value: stored.version });
        radio.dataset.side = side;
        // The default comparison: the version before the latest against the latest.
        radio.checked = stored.version === (side === 'a' ? Math.max(1, newest - 1) : newest);
        const label = document.createElement('label');
        label.append(radio, side.toUpperCase());
        return label;
      };
      const cells = [open, `${stored.created_at}`, pick('a'), pick('b')];
      for (const cell of cells) {
        const td = document.createElement('td');
        td.append(cell);
        tr.append(td);
      }
      list.append(tr);
    }
    const older = newest - numbers.length;
    if (older > 0) {
      const tr = document.createElement('tr');
      tr.append(Object.assign(document.createElement('td'), { colSpan: 4, className: 'muted',
        textContent: `and ${older} older version${older === 1 ? '' : 's'}, not listed` }));
      list.append(tr);
    }
    $('versions').hidden = false;
    $('compare').disabled = newest < 2;
  }

  async function compare() {
    const a = Number(document.querySelector('input[name="compare-a"]:checked').value);
    const b = Number(document.querySelector('input[name="compare-b"]:checked').value);
    const [sa, sb] = await Promise.all([version(a), version(b)]);
    const rows = object.kind === 'part'
      ? await Promise.all([a, b].map((n) => api(`/parts/${object.id}/params?version=${n}`))).then(([va, vb]) =>
        PART_VALUES.map(([path, label]) => [label, valueAt(va, path), valueAt(vb, path)]))
      : Object.keys({ ...sa.document, ...sb.document }).map((key) => [key, sa.document[key], sb.document[key]]);
    const table = document.createElement('table');
    table.id = 'compare-values';
    table.innerHTML = `<tr><th></th><th>version ${a} (A, blue)</th><th>version ${b} (B, red)</th></tr>`;
    for (const [label, va, vb] of rows) {
      const tr = document.createElement('tr');
      tr.classList.toggle('differs', JSON.stringify(va) !== JSON.stringify(vb));
      for (const text of [label, fuzzyText(va), fuzzyText(vb)]) tr.append(Object.assign(document.createElement('td'), { textContent: text }));
      table.append(tr);
    }
    $('compare-box').replaceChildren(table);
    const draw = async () => {
      view.busy(true);
      view.status(`computing versions ${a} and ${b}…`);
      try {
        const alpha = view.alpha();
        const [ma, mb] = await Promise.all([sa, sb].map((s) => view.fetchDocumentScene(s.document, alpha, 48)));
        const both = new THREE.Group();
        both.add(tinted(ma, 0x4673cd), tinted(mb, 0xd0402b));
        view.showModel(both, true);
        view.status(`version ${a} (blue) and version ${b} (red) at α = ${alpha.toFixed(2)}`);
        $('canvas').dataset.shown = `compare:${a},${b}@${alpha}`;
      } finally {
        view.busy(false);
      }
    };
    view.own(draw);
    await draw();
  }

  $('history').addEventListener('click', () => history().catch((e) => view.status(e.message)));
  $('compare').addEventListener('click', () => compare().catch((e) => view.status(e.message)));

  return {
    opened(o) {
      object = { kind: o.kind, id: o.id, latest: o.version };
      documents.clear();
      $('versions').hidden = true;
      $('compare-box').replaceChildren();
    },
  };
}
