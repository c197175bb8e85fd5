// Editing a part's fourteen fuzzy values (the nine parameters, scale, rotation angle and the three
// translations; docs/api.md §2) with the view following: every edit asks POST /mesh for a coarse
// preview (24 voxels across), and a pause for the full one (64). Save stores the edit as a new
// version with PUT and If-Match, so a version someone else saved meanwhile is a 412 that the
// editor reports (with a reload), never a lost update. The values come from GET
// /parts/{id}/params, where a part made from words has them resolved.
import { api } from './api.js';

const $ = (id) => document.getElementById(id);

// [path in the part document, label, slider range]. The ranges are where the slider moves a
// value's core; the server checks the real ranges (docs/api.md §2) and the editor shows its word.
export const PART_VALUES = [
  ['params.eps1', 'eps1 (squareness n–s)', [0.1, 4]],
  ['params.eps2', 'eps2 (squareness e–w)', [0.1, 4]],
  ['params.a1', 'a1 (size)', [0.05, 5]],
  ['params.a2', 'a2 (ratio y)', [0.05, 5]],
  ['params.a3', 'a3 (ratio z)', [0.05, 5]],
  ['params.kx', 'kx (taper x)', [-1, 1]],
  ['params.ky', 'ky (taper y)', [-1, 1]],
  ['params.kv', 'kv (bend)', [-1, 1]],
  ['params.t', 't (twist)', [-6.28, 6.28]],
  ['transform.scale', 'scale', [0.1, 4]],
  ['transform.rotate.deg', 'rotate (deg)', [-180, 180]],
  ['transform.translate.0', 'translate x', [-5, 5]],
  ['transform.translate.1', 'translate y', [-5, 5]],
  ['transform.translate.2', 'translate z', [-5, 5]],
];

export function valueAt(values, path) {
  return path.split('.').reduce((o, k) => (o === undefined ? undefined : o[k]), values);
}

function setValueAt(values, path, value) {
  const keys = path.split('.');
  const last = keys.pop();
  keys.reduce((o, k) => o[k], values)[last] = value;
}

// ---- a fuzzy value in the editor's terms ------------------------------------------------------
// {form, xs}: crisp [v]; about [core, spread] (a symmetric triangle); tri [l, m, r];
// trap [a, b, c, d]; points (kept as given, [[x, mu], …], moved only as a whole).
export function fromJson(v) {
  if (typeof v === 'number') return { form: 'crisp', xs: [v] };
  if (v.tri) return { form: 'tri', xs: [...v.tri] };
  if (v.trap) return { form: 'trap', xs: [...v.trap] };
  if (v.about !== undefined) return { form: 'about', xs: [v.about, v.spread ?? 0] };
  if (v.points) return { form: 'points', xs: v.points.map((p) => [...p]) };
  throw new Error(`a fuzzy value the editor does not know: ${JSON.stringify(v)}`);
}

export function toJson(f) {
  switch (f.form) {
    case 'crisp': return f.xs[0];
    case 'about': return { about: f.xs[0], spread: f.xs[1] };
    case 'tri': return { tri: [...f.xs] };
    case 'trap': return { trap: [...f.xs] };
    default: return { points: f.xs.map((p) => [...p]) };
  }
}

// The support [lo, hi] and core [c1, c2] of a value.
function supportAndCore(f) {
  switch (f.form) {
    case 'crisp': return { lo: f.xs[0], hi: f.xs[0], c1: f.xs[0], c2: f.xs[0] };
    case 'about': return { lo: f.xs[0] - f.xs[1], hi: f.xs[0] + f.xs[1], c1: f.xs[0], c2: f.xs[0] };
    case 'tri': return { lo: f.xs[0], hi: f.xs[2], c1: f.xs[1], c2: f.xs[1] };
    case 'trap': return { lo: f.xs[0], hi: f.xs[3], c1: f.xs[1], c2: f.xs[2] };
    default: {
      const core = f.xs.filter((p) => p[1] === 1).map((p) => p[0]);
      return { lo: f.xs[0][0], hi: f.xs[f.xs.length - 1][0], c1: Math.min(...core), c2: Math.max(...core) };
    }
  }
}

// The α-cut [lo, hi] of a value: l + α(m − l) to r − α(r − m) for a triangle (docs/api.md §6), the
// support at α = 0 and the core at 1; a points value is linear between its points.
export function alphaCut(f, alpha) {
  if (f.form !== 'points') {
    const { lo, hi, c1, c2 } = supportAndCore(f);
    return [lo + alpha * (c1 - lo), hi - alpha * (hi - c2)];
  }
  const xs = [];
  f.xs.forEach(([x, mu], i) => {
    if (mu >= alpha) xs.push(x);
    const next = f.xs[i + 1];
    if (next && (mu - alpha) * (next[1] - alpha) < 0) xs.push(x + ((alpha - mu) / (next[1] - mu)) * (next[0] - x));
  });
  return [Math.min(...xs), Math.max(...xs)];
}

export function coreMidpoint(f) {
  const { c1, c2 } = supportAndCore(f);
  return (c1 + c2) / 2;
}

// The same value moved so that its core's midpoint is at `mid` (its shape kept).
export function movedTo(f, mid) {
  const d = mid - coreMidpoint(f);
  if (f.form === 'points') return { form: 'points', xs: f.xs.map(([x, mu]) => [x + d, mu]) };
  if (f.form === 'about') return { form: 'about', xs: [f.xs[0] + d, f.xs[1]] };
  return { form: f.form, xs: f.xs.map((x) => x + d) };
}

// The value in another form, keeping its support and core; a crisp value becoming fuzzy gets a
// spread of a tenth of itself (at least 0.1), as "about N" does.
export function convertedTo(f, form) {
  let { lo, hi, c1, c2 } = supportAndCore(f);
  if (lo === hi && form !== 'crisp') {
    const s = Math.max(0.1 * Math.abs(lo), 0.1);
    lo -= s;
    hi += s;
  }
  const m = (c1 + c2) / 2;
  switch (form) {
    case 'crisp': return { form, xs: [m] };
    case 'about': return { form, xs: [m, Math.max(m - lo, hi - m)] };
    case 'tri': return { form, xs: [lo, m, hi] };
    case 'trap': return { form, xs: [lo, c1, c2, hi] };
    default: return f;
  }
}

// Why a value cannot be sent yet (points out of order while being typed), or '' when it can.
export function disorder(f) {
  if (f.form === 'points') return '';
  if (!f.xs.every(Number.isFinite)) return f.form === 'crisp' ? 'a number' : 'numbers';
  if (f.form === 'about') return f.xs[1] < 0 ? 'a spread of at least 0' : '';
  for (let i = 1; i < f.xs.length; i++) if (f.xs[i] < f.xs[i - 1]) return 'points in increasing order';
  return '';
}

// A value as text (the structure panel, the comparison), its numbers to 4 significant digits.
export function fuzzyText(v) {
  const n = (x) => (typeof x === 'number' ? String(Number(x.toPrecision(4))) : String(x));
  if (v === undefined) return '—';
  if (typeof v !== 'object' || v === null) return n(v);
  if (v.tri) return `tri(${v.tri.map(n).join(', ')})`;
  if (v.trap) return `trap(${v.trap.map(n).join(', ')})`;
  if (v.about !== undefined) return `about ${n(v.about)}${v.spread !== undefined ? ` ± ${n(v.spread)}` : ''}`;
  return JSON.stringify(v);
}

const FIELD_NAMES = { crisp: ['value'], about: ['core', 'spread'], tri: ['l', 'm', 'r'], trap: ['a', 'b', 'c', 'd'] };
const round = (x) => Number(x.toPrecision(6));

// ---- the editor -------------------------------------------------------------------------------
export function setupEditor(view) {
  let part = null;     // {id, version (the one edited), latest (for If-Match), document, values}
  let edits = 0;       // edits since the load; a preview of an older edit is not shown
  let loads = 0;       // loads so far; nor is one of an edit before the last load
  let wanted = null;   // the next preview to ask for: {edit, load, resolution}
  let inFlight = false;
  let fineTimer = null;

  function editorStatus(text, error = false) {
    $('editor-status').replaceChildren(text);
    $('editor-status').style.color = error ? '#b00' : '';
  }

  // The edited part as a document: the stored one with the edited values.
  // (A part made from words keeps its text: every value is now given, and given values override
  // the words one by one.)
  function editedDocument() {
    return { ...part.document, kind: 'part', params: part.values.params, transform: part.values.transform };
  }

  // One preview request at a time: while one is out, only the newest edit waits to be asked, so
  // a fast drag costs the server one coarse mesh at a time and the view shows the latest answer.
  async function pump() {
    if (inFlight || !wanted) return;
    const job = wanted;
    wanted = null;
    inFlight = true;
    view.busy(true);
    view.status(`computing ${job.resolution < 64 ? 'a coarse preview' : 'the full mesh'}…`);
    try {
      const scene = await view.fetchDocumentScene(editedDocument(), view.alpha(), job.resolution);
      if (job.edit === edits && job.load === loads) {
        view.showModel(scene);
        const fine = job.resolution >= 64;
        view.status(`edited, not saved: ${fine ? '' : 'coarse preview; '}α = ${view.alpha().toFixed(2)}`);
        // For the page test: which preview is on screen, and every one shown since the load.
        const shown = `${fine ? 'fine' : 'coarse'}:${job.edit}`;
        $('canvas').dataset.preview = shown;
        $('canvas').dataset.previewLog = `${$('canvas').dataset.previewLog || ''} ${shown}`.trim();
        editorStatus(`${edits} edit${edits === 1 ? '' : 's'}, not saved`);
      }
    } catch (e) {
      // A value the server refuses (out of its range): said in the editor, the last picture kept.
      if (job.edit === edits && job.load === loads) {
        editorStatus(e.message, true);
        view.status('no preview of this edit: the server refused it (see the values)');
      }
    } finally {
      inFlight = false;
      view.busy(wanted !== null);
      pump();
    }
  }

  function preview(resolution = 24) {
    wanted = { edit: edits, load: loads, resolution };
    pump();
  }

  function edited() {
    edits += 1;
    const bad = PART_VALUES.map(([path, label]) => [label, disorder(fromJson(valueAt(part.values, path)))]).find(([, why]) => why);
    $('save-version').disabled = Boolean(bad);
    clearTimeout(fineTimer);
    if (bad) {
      editorStatus(`${bad[0]} needs ${bad[1]}`, true);
      return;
    }
    view.own(() => {
      preview(64);
      return Promise.resolve();
    });
    preview(24);
    // The full mesh once the edits pause.
    fineTimer = setTimeout(() => preview(64), 600);
  }

  function input(attrs) {
    return Object.assign(document.createElement('input'), attrs);
  }

  function valueRow([path, label, range]) {
    const tr = document.createElement('tr');
    tr.dataset.value = path;
    const th = document.createElement('th');
    th.textContent = label;
    const form = document.createElement('select');
    form.dataset.action = 'edit-value';
    form.dataset.value = path;
    form.dataset.field = 'form';
    for (const [v, text] of [['crisp', 'crisp'], ['about', 'core ± spread'], ['tri', 'triangle'], ['trap', 'trapezoid'], ['points', 'points']])
      form.append(Object.assign(document.createElement('option'), { value: v, textContent: text }));
    const numbers = document.createElement('span');
    numbers.className = 'numbers';
    // The slider's range reaches the value's core wherever it lies.
    const mid = coreMidpoint(fromJson(valueAt(part.values, path)));
    const slider = input({ type: 'range', min: Math.min(range[0], mid), max: Math.max(range[1], mid), step: 'any' });
    slider.dataset.action = 'edit-value';
    slider.dataset.value = path;
    slider.dataset.field = 'core';
    slider.title = 'drag to move the value (its shape kept)';

    const current = () => fromJson(valueAt(part.values, path));
    const set = (f) => setValueAt(part.values, path, toJson(f));
    function fill() {
      const f = current();
      form.value = f.form;
      form.querySelector('option[value="points"]').disabled = f.form !== 'points';
      slider.value = coreMidpoint(f);
      numbers.replaceChildren();
      if (f.form === 'points') {
        numbers.append(input({ value: JSON.stringify(f.xs), readOnly: true, className: 'points', title: 'piecewise linear: move it with the slider' }));
        return;
      }
      FIELD_NAMES[f.form].forEach((name, i) => {
        const box = input({ type: 'number', step: 'any', value: round(f.xs[i]), title: name, placeholder: name });
        box.dataset.action = 'edit-value';
        box.dataset.value = path;
        box.dataset.field = name;
        box.addEventListener('input', () => {
          const g = current();
          g.xs[i] = box.value === '' ? NaN : Number(box.value);
          set(g);
          slider.value = coreMidpoint(g);
          edited();
        });
        numbers.append(box);
      });
    }
    form.addEventListener('change', () => {
      set(convertedTo(current(), form.value));
      fill();
      edited();
    });
    slider.addEventListener('input', () => {
      set(movedTo(current(), Number(slider.value)));
      const f = current();
      [...numbers.querySelectorAll('input[type="number"]')].forEach((box, i) => { box.value = round(f.xs[i]); });
      if (f.form === 'points') fill();
      edited();
    });
    fill();
    tr.append(th);
    for (const control of [form, numbers, slider]) {
      const td = document.createElement('td');
      td.append(control);
      tr.append(td);
    }
    return tr;
  }

  // Loads version `version` of the part (default: the latest) into the editor.
  async function load(id, version = null) {
    const [values, stored] = await Promise.all([
      api(`/parts/${id}/params${version ? `?version=${version}` : ''}`),
      api(`/parts/${id}${version ? `?version=${version}` : ''}`),
    ]);
    part = { id, version: stored.version, latest: stored.latest_version, document: stored.document,
      values: { params: values.params, transform: values.transform } };
    edits = 0;
    loads += 1;
    wanted = null;
    clearTimeout(fineTimer);
    delete $('canvas').dataset.preview;
    delete $('canvas').dataset.previewLog;
    $('editor-values').replaceChildren(...PART_VALUES.map(valueRow));
    $('save-version').disabled = true;
    editorStatus(`version ${part.version}${part.version === part.latest ? '' : ` (of ${part.latest})`}: every value as the server reads it`);
  }

  async function save() {
    const button = $('save-version');
    button.disabled = true;
    editorStatus('saving…');
    try {
      const saved = await api(`/parts/${part.id}`, {
        method: 'PUT',
        headers: { 'If-Match': `"${part.latest}"` },
        body: JSON.stringify(editedDocument()),
      });
      await view.reopen();
      editorStatus(`saved as version ${saved.version}`);
    } catch (e) {
      if (e.status !== 412) {
        editorStatus(e.message, true);
        button.disabled = false;
        return;
      }
      // Someone else stored a version after the one this edit started from: say so, keep the
      // edit on screen, and offer the current version (the edit is then dropped).
      const reload = Object.assign(document.createElement('button'), { type: 'button', textContent: 'Reload' });
      reload.dataset.action = 'reload';
      reload.addEventListener('click', () => view.reopen());
      $('editor-status').replaceChildren('This part was changed by someone else since you opened it: your edit is not saved. ', reload,
        ' the current version (your edit is dropped).');
      $('editor-status').style.color = '#b00';
      $('editor').dataset.conflict = 'true';
    }
  }
  $('save-version').addEventListener('click', () => save());

  return {
    // A stored object opened in the view: a part's values go into the editor.
    opened(object) {
      $('editor').hidden = object.kind !== 'part';
      delete $('editor').dataset.conflict;
      part = null;
      return object.kind === 'part' ? load(object.id).catch((e) => editorStatus(e.message, true)) : Promise.resolve();
    },
    // Version `version` opened from the history: edit that one (saved on top of the latest).
    loadVersion(id, version) {
      return load(id, version);
    },
  };
}
