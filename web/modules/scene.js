// What every 3D picture of the page shares: a white scene lit from above front left, and a camera
// that looks at an object from the front right and above (as the server's thumbnails do).
import * as THREE from 'three';

export function litScene() {
  const scene = new THREE.Scene();
  scene.background = new THREE.Color(0xffffff);
  scene.add(new THREE.HemisphereLight(0xffffff, 0x8090a0, 1.6));
  const sun = new THREE.DirectionalLight(0xffffff, 1.8);
  sun.position.set(-2, 5, 3);
  scene.add(sun);
  return scene;
}

// Puts `camera` three radii from the centre of `object`'s bounding box; returns that centre.
export function fitCamera(camera, object) {
  const box = new THREE.Box3().setFromObject(object);
  const centre = box.getCenter(new THREE.Vector3());
  const radius = box.getSize(new THREE.Vector3()).length() / 2 || 1;
  camera.position.copy(centre).add(new THREE.Vector3(1, 0.9, 1.6).normalize().multiplyScalar(radius * 3));
  camera.near = radius / 100;
  camera.far = radius * 100;
  camera.updateProjectionMatrix();
  return centre;
}
