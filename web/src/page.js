// The interactive page of a scene (impulse export): the bodies of the scene's one run, drawn with
// three.js at each video frame's poses, played, paused, scrubbed and orbited. The program writes
// the run into the page as JSON (<script id="impulse-run" type="application/json">, demos/page/);
// nothing is fetched. Test hook: #probe=T1,T2 writes each body's drawn pose at those moments into
// <pre id="probe">, and every error into <pre id="errors">.
import * as THREE from 'three';
import { OrbitControls } from 'three/addons/controls/OrbitControls.js';

const errors = [];
function report(text) {
  errors.push(text);
  const pre = document.getElementById('errors');
  if (pre) pre.textContent = errors.join('\n');
}
window.addEventListener('error', (event) => report('error: ' + event.message));
window.addEventListener('unhandledrejection', (event) => report('rejection: ' + event.reason));

const run = JSON.parse(document.getElementById('impulse-run').textContent);
const bodyCount = run.bodies.length;
document.getElementById('title').textContent = run.title;
document.title = run.title + ' \u2014 impulse';
const frameCount = run.frames.length;

// sRGB colours as the video draws them.
const colourOf = (c) => new THREE.Color().setRGB(c[0], c[1], c[2], THREE.SRGBColorSpace);

function geometryOf(body) {
  switch (body.shape) {
    case 'sphere': return new THREE.SphereGeometry(body.radius, 48, 24);
    case 'box': return new THREE.BoxGeometry(2 * body.half_extents[0], 2 * body.half_extents[1], 2 * body.half_extents[2]);
    case 'cylinder': return new THREE.CylinderGeometry(body.radius, body.radius, 2 * body.half_height, 64);
    case 'capsule': return new THREE.CapsuleGeometry(body.radius, 2 * body.half_height, 16, 48);
    case 'hull':
    case 'mesh': {
      const geometry = new THREE.BufferGeometry();
      geometry.setAttribute('position', new THREE.Float32BufferAttribute(body.triangles, 3));
      geometry.computeVertexNormals();  // flat: each triangle's corners are its own
      return geometry;
    }
    default: return null;
  }
}

// A plane: the ground where it is horizontal, else a thin slab in its colour (as the video draws it).
function planeOf(body, material) {
  const n = new THREE.Vector3(...body.normal);
  const size = 400;
  const mesh = new THREE.Mesh(new THREE.BoxGeometry(size, 0.02, size), material);
  mesh.quaternion.setFromUnitVectors(new THREE.Vector3(0, 1, 0), n);
  mesh.position.copy(n.clone().multiplyScalar(body.offset - 0.01));
  return mesh;
}

const renderer = new THREE.WebGLRenderer({ antialias: true, preserveDrawingBuffer: true });
renderer.setPixelRatio(window.devicePixelRatio);
const view = document.getElementById('view');
view.appendChild(renderer.domElement);
const scene = new THREE.Scene();
scene.background = new THREE.Color().setRGB(0.92, 0.93, 0.96, THREE.SRGBColorSpace);
scene.add(new THREE.HemisphereLight(0xffffff, 0x8090a0, 1.6));
const sun = new THREE.DirectionalLight(0xffffff, 1.8);
sun.position.set(4, 10, 6);
scene.add(sun);

const camera = new THREE.PerspectiveCamera(run.camera.fov_y_degrees, 16 / 9, 0.05, 2000);
camera.position.set(...run.camera.position);
const controls = new OrbitControls(camera, renderer.domElement);
controls.target.set(...run.camera.target);
controls.update();

const objects = run.bodies.map((body) => {
  const material = new THREE.MeshStandardMaterial({ color: colourOf(body.colour), roughness: 0.6, metalness: 0.0,
                                                     flatShading: body.shape === 'hull' || body.shape === 'mesh',
                                                     side: body.shape === 'mesh' ? THREE.DoubleSide : THREE.FrontSide });
  const object = body.shape === 'plane' ? planeOf(body, material) : new THREE.Mesh(geometryOf(body), material);
  object.name = body.name;
  scene.add(object);
  return object;
});

// Frame k's poses: per body x, y, z, then the quaternion w, x, y, z.
function showFrame(k) {
  const frame = run.frames[k];
  for (let i = 0; i < bodyCount; ++i) {
    if (run.bodies[i].shape === 'plane') continue;
    const p = 7 * i;
    objects[i].position.set(frame[p], frame[p + 1], frame[p + 2]);
    objects[i].quaternion.set(frame[p + 4], frame[p + 5], frame[p + 6], frame[p + 3]);
  }
}

const slider = document.getElementById('time');
const clock = document.getElementById('clock');
const playButton = document.getElementById('play');
const speed = document.getElementById('speed');
slider.max = String(frameCount - 1);
let frame = 0;
let playing = false;
let started = 0;   // ms: when frame 0 would have been shown at this speed
function setFrame(k) {
  frame = Math.max(0, Math.min(frameCount - 1, k));
  slider.value = String(frame);
  clock.textContent = 't = ' + (frame / run.fps).toFixed(2) + ' s';
  showFrame(frame);
}
function play(on) {
  playing = on;
  playButton.textContent = on ? 'Pause' : 'Play';
  if (on) {
    if (frame >= frameCount - 1) setFrame(0);
    started = performance.now() - (1000 * frame) / (run.fps * Number(speed.value));
  }
}
playButton.addEventListener('click', () => play(!playing));
slider.addEventListener('input', () => { play(false); setFrame(Number(slider.value)); });
speed.addEventListener('change', () => play(playing));
document.getElementById('back').addEventListener('click', () => { play(false); setFrame(frame - 1); });
document.getElementById('forward').addEventListener('click', () => { play(false); setFrame(frame + 1); });
document.addEventListener('keydown', (event) => {
  if (event.key === ' ') { play(!playing); event.preventDefault(); }
  if (event.key === 'ArrowLeft') { play(false); setFrame(frame - 1); }
  if (event.key === 'ArrowRight') { play(false); setFrame(frame + 1); }
});

function resize() {
  const width = view.clientWidth, height = view.clientHeight;
  renderer.setSize(width, height, false);
  camera.aspect = width / height;
  camera.updateProjectionMatrix();
}
window.addEventListener('resize', resize);
resize();

renderer.setAnimationLoop(() => {
  if (playing) {
    const k = Math.floor(((performance.now() - started) / 1000) * run.fps * Number(speed.value));
    if (k >= frameCount - 1) { setFrame(frameCount - 1); play(false); } else if (k !== frame) setFrame(k);
  }
  controls.update();
  renderer.render(scene, camera);
});
setFrame(0);

// The test hook: the drawn poses (each object's world matrix) at the frames of the asked moments.
const probe = /#probe=([0-9.,]+)/.exec(window.location.hash);
if (probe) {
  const lines = [];
  for (const text of probe[1].split(',')) {
    const k = Math.round(Number(text) * run.fps);
    setFrame(k);
    scene.updateMatrixWorld(true);
    objects.forEach((object, i) => {
      if (run.bodies[i].shape === 'plane') return;
      const position = new THREE.Vector3(), rotation = new THREE.Quaternion(), scale = new THREE.Vector3();
      object.matrixWorld.decompose(position, rotation, scale);
      lines.push(['POSE', (k / run.fps).toFixed(6), position.x, position.y, position.z, rotation.w, rotation.x, rotation.y, rotation.z, run.bodies[i].name].join(' '));
    });
  }
  renderer.render(scene, camera);
  lines.push('GL ' + (renderer.getContext() ? 'yes' : 'no'));
  document.getElementById('probe').textContent = lines.join('\n');
}
window.impulsePage = { frameCount, setFrame, errors };
