// Curves and surfaces in the view.
// - A Bézier curve: its lower, crisp and upper curves at the slider's α (GET /curves/{id}/svg).
// - A fair curve (Bernardes, Wu & D'Ottaviano): its ranked candidates (GET /curves/{id}/candidates),
//   any one highlighted in the picture (?candidate=k), and one chosen as the designer's: stored
//   as the document's chosen_candidate in a new version (PUT with If-Match), marked in the list and
//   drawn by default afterwards. The paper makes the user part of the defuzzification.
// - A surface: its lower and upper surfaces at α (GET /surfaces/{id}/mesh, OBJ) in the 3D view
//   with their control nets at α (the lower and upper ends of each control coordinate's α-cut,
//   which de Casteljau turns into those surfaces: docs/api.md §6).
import * as THREE from 'three';
import { OBJLoader } from 'three/addons/loaders/OBJLoader.js';
import { ApiError, api, apiBytes } from './api.js';
import { alphaCut, fromJson } from './part_editor.js';

const $ = (id) => document.getElementById(id);

const COLOURS = { lower: 0x4673cd, upper: 0xeb8232 };

// The control net of `grid` (control_grid[i][j], each coordinate fuzzy) at `alpha`, at the `end`
// (0: lower, 1: upper) of every coordinate's cut, as line segments along i and along j.
export function controlNet(grid, alpha, end) {
  const point = (p) => [0, 1, 2].map((c) => (c < p.length ? alphaCut(fromJson(p[c]), alpha)[end] : 0));
  const pts = grid.map((row) => row.map(point));
  const segments = [];
  pts.forEach((row, i) => row.forEach((p, j) => {
    if (j + 1 < row.length) segments.push(p, row[j + 1]);
    if (i + 1 < pts.length) segments.push(p, pts[i + 1][j]);
  }));
  return { points: pts.flat(), segments };
}

export function setupCurves(view) {
  let object = null;  // the curve or surface shown: {kind, id, version, document}

  function curveStatus(text, error = false) {
    $('candidates-status').textContent = text;
    $('candidates-status').style.color = error ? '#b00' : '';
  }

  // The SVG picture; `shown` (for the page test) once it has loaded.
  function picture(query, shown) {
    const img = $('curve-svg');
    return new Promise((resolve, reject) => {
      img.onload = () => {
        img.dataset.shown = shown;
        resolve();
      };
      img.onerror = () => reject(new Error('the curve\'s picture did not load'));
      img.src = `/curves/${object.id}/svg?version=${object.version}${query}`;
    });
  }

  async function drawBezier() {
    const alpha = view.alpha();
    await picture(`&alpha=${alpha}`, `curve/${object.id}@${alpha}`);
    view.status(`lower(α), crisp and upper(α) curves at α = ${alpha.toFixed(2)}`);
  }

  async function showCandidate(k) {
    for (const li of $('candidates').children) li.classList.toggle('selected', Number(li.dataset.candidate) === k);
    await picture(`&candidate=${k}`, `curve/${object.id}#${k}`);
  }

  async function choose(k) {
    const doc = { ...object.document, chosen_candidate: k };
    try {
      await api(`/curves/${object.id}`, { method: 'PUT', headers: { 'If-Match': `"${object.version}"` }, body: JSON.stringify(doc) });
      await view.reopen();
      curveStatus(`candidate ${k + 1} chosen (version ${object.version})`);
    } catch (e) {
      curveStatus(e instanceof ApiError && e.status === 412
        ? 'This curve was changed by someone else since you opened it: open it again to choose.' : e.message, true);
    }
  }

  function candidateItem(c, k) {
    const li = document.createElement('li');
    li.dataset.candidate = k;
    const chosen = object.document.chosen_candidate === k;
    li.classList.toggle('chosen', chosen);
    li.append(`score ${c.score.toFixed(3)} · point ${c.point + 1} at ${c.angles_deg[c.point].toFixed(1)}° `);
    if (chosen) li.append(Object.assign(document.createElement('b'), { className: 'mark', textContent: '✓ your choice ' }));
    const pick = Object.assign(document.createElement('button'), { type: 'button', textContent: chosen ? 'chosen' : 'choose' });
    pick.dataset.action = 'choose-candidate';
    pick.disabled = chosen;
    pick.addEventListener('click', (event) => {
      event.stopPropagation();
      choose(k);
    });
    li.append(pick);
    li.addEventListener('click', () => showCandidate(k).catch((e) => curveStatus(e.message, true)));
    return li;
  }

  async function openFair() {
    const answer = await api(`/curves/${object.id}/candidates?version=${object.version}`);
    const { candidates } = answer;
    $('candidates').replaceChildren(...candidates.map(candidateItem));
    $('candidates-box').hidden = false;
    const chosen = object.document.chosen_candidate;
    curveStatus(candidates.length ? (chosen === undefined ? 'no candidate chosen yet: the best is drawn' : '') : 'no candidate reaches alpha_threshold');
    // α does not apply (the slider is hidden): the candidates are crisp curves, their fuzziness
    // is in the ranking.
    view.own(() => Promise.resolve());
    view.status('a fair curve: its candidates are crisp curves, ranked by the danger zones');
    if (candidates.length) await showCandidate(chosen ?? 0);
  }

  async function drawSurface() {
    const alpha = view.alpha();
    const { id } = object;
    const loader = new OBJLoader();
    const group = new THREE.Group();
    view.busy(true);
    try {
      for (const [end, bound] of [[0, 'lower'], [1, 'upper']]) {
        const text = new TextDecoder().decode(await apiBytes(`/surfaces/${id}/mesh?version=${object.version}&bound=${bound}&alpha=${alpha}`));
        const sheet = loader.parse(text);
        const material = new THREE.MeshStandardMaterial({ color: COLOURS[bound], roughness: 0.6, side: THREE.DoubleSide,
          ...(bound === 'upper' ? { transparent: true, opacity: 0.45, depthWrite: false } : {}) });
        sheet.traverse((o) => {
          if (o.isMesh) {
            o.material = material;
            o.name = bound;
            o.renderOrder = end;
          }
        });
        group.add(sheet);
        const net = controlNet(object.document.bezier.control_grid, alpha, end);
        const lines = new THREE.LineSegments(new THREE.BufferGeometry().setFromPoints(net.segments.map((p) => new THREE.Vector3(...p))),
          new THREE.LineBasicMaterial({ color: COLOURS[bound] }));
        lines.name = `${bound}-net`;
        const dots = new THREE.Points(new THREE.BufferGeometry().setFromPoints(net.points.map((p) => new THREE.Vector3(...p))),
          new THREE.PointsMaterial({ color: COLOURS[bound], size: 6, sizeAttenuation: false }));
        group.add(lines, dots);
      }
      if (object.id !== id) return;
      view.showModel(group, true);
      view.status(`lower(α) and upper(α) surfaces with their control nets at α = ${alpha.toFixed(2)}`);
      $('canvas').dataset.shown = `surface/${id}@${alpha}`;
    } finally {
      view.busy(false);
    }
  }

  return {
    opened(o) {
      $('candidates-box').hidden = true;
      $('candidates').replaceChildren();
      if (o.kind !== 'curve' && o.kind !== 'surface') {
        object = null;
        return Promise.resolve();
      }
      object = o;
      $('view').dataset.curve = o.document.fair ? 'fair' : 'bezier';
      if (o.kind === 'surface') {
        view.own(drawSurface);
        return drawSurface();
      }
      if (o.document.fair) return openFair();
      view.own(drawBezier);
      return drawBezier();
    },
  };
}
