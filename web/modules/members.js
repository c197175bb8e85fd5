// The family's members (Zhang, Pham & Chen, Figure 1; GET /{kind}s/{id}/members): a gallery of
// crisp members of the fuzzy shape, each with its membership degree, from the core (1) outward.
// Each card's picture is the member's mesh (POST /mesh of its document, 20 voxels across) drawn in
// the page, one at a time so that the gallery never holds more than one heavy request; a click
// shows the member in the view at full resolution.
import * as THREE from 'three';
import { api } from './api.js';
import { fitCamera, litScene } from './scene.js';

const $ = (id) => document.getElementById(id);

const COUNT = 9;
const CARD_PIXELS = 112;

// One small renderer draws every card (a canvas each would be a WebGL context each).
let cardRenderer = null;
function drawCard(model, canvas) {
  if (!cardRenderer) {
    cardRenderer = new THREE.WebGLRenderer({ antialias: true, preserveDrawingBuffer: true });
    cardRenderer.setSize(CARD_PIXELS, CARD_PIXELS, false);
  }
  const scene = litScene();
  const material = new THREE.MeshStandardMaterial({ color: 0x4673cd, roughness: 0.6 });
  model.traverse((o) => { if (o.isMesh) o.material = material; });
  scene.add(model);
  const camera = new THREE.PerspectiveCamera(40, 1, 0.01, 1000);
  camera.lookAt(fitCamera(camera, model));
  cardRenderer.render(scene, camera);
  canvas.getContext('2d').drawImage(cardRenderer.domElement, 0, 0, CARD_PIXELS, CARD_PIXELS);
}

export function setupMembers(view) {
  let object = null;
  let gallery = 0;  // galleries asked for; a newer one stops drawing the older one's cards

  function showMember(k, member) {
    const draw = async () => {
      view.busy(true);
      view.status(`computing member ${k}…`);
      try {
        view.showModel(await view.fetchDocumentScene(member.document, view.alpha(), 48));
        view.status(`member ${k}: membership ${member.membership.toFixed(2)} (a crisp member: the same at every α)`);
        $('canvas').dataset.shown = `member:${k}`;
      } finally {
        view.busy(false);
      }
    };
    for (const li of $('members').children) li.classList.toggle('selected', Number(li.dataset.member) === k);
    view.own(draw);
    return draw();
  }

  async function members() {
    const which = ++gallery;
    const answer = await api(`/${object.kind}s/${object.id}/members?count=${COUNT}`);
    const cards = answer.members.map((member, k) => {
      const li = document.createElement('li');
      li.dataset.member = k;
      li.dataset.membership = member.membership;
      const canvas = Object.assign(document.createElement('canvas'), { width: CARD_PIXELS, height: CARD_PIXELS });
      const degree = Object.assign(document.createElement('div'), { className: 'degree', textContent: `μ = ${member.membership.toFixed(2)}` });
      li.append(canvas, degree);
      li.title = k === 0 ? 'the core: every value at its core\'s midpoint' : `every value at an end of its cut at α = ${member.level}`;
      li.addEventListener('click', () => showMember(k, member).catch((e) => view.status(e.message)));
      return { li, canvas, member };
    });
    $('members').replaceChildren(...cards.map((c) => c.li));
    $('members-box').hidden = false;
    for (const { li, canvas, member } of cards) {
      if (which !== gallery) return;
      drawCard(await view.fetchDocumentScene(member.document, 0.5, 20), canvas);
      li.dataset.drawn = 'true';
    }
  }

  $('members-button').addEventListener('click', () => members().catch((e) => view.status(e.message)));

  return {
    opened(o) {
      object = { kind: o.kind, id: o.id };
      gallery += 1;
      $('members-box').hidden = true;
      $('members').replaceChildren();
    },
  };
}
