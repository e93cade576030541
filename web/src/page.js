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

// A plane: the ground where it is horizontal (the video's light grey, a line every metre), else a
// thin slab in its colour whose top face lies in the plane.
function planeOf(body, material) {
  const n = new THREE.Vector3(...body.normal);
  const size = 400;
  const ground = n.y > 0.999;
  if (ground) material.color.setRGB(0.84, 0.85, 0.86, THREE.SRGBColorSpace);
  const mesh = new THREE.Mesh(new THREE.BoxGeometry(size, 0.02, size), material);
  mesh.quaternion.setFromUnitVectors(new THREE.Vector3(0, 1, 0), n);
  mesh.position.copy(n.clone().multiplyScalar(body.offset - 0.01));
  mesh.receiveShadow = true;
  if (ground) {
    // A line every metre over 100 m, in metre-long pieces: a line through the near plane is
    // clipped wrongly by some WebGL implementations (SwiftShader), and these are short.
    const corners = [];
    const y = body.offset + 0.003;  // 3 mm above the ground, clear of its depth
    for (let a = -50; a <= 50; ++a)
      for (let b = -50; b < 50; ++b) corners.push(a, y, b, a, y, b + 1, b, y, a, b + 1, y, a);
    const lines = new THREE.BufferGeometry();
    lines.setAttribute('position', new THREE.Float32BufferAttribute(corners, 3));
    scene.add(new THREE.LineSegments(lines, new THREE.LineBasicMaterial({ color: 0xb0b4bc })));
  }
  return mesh;
}

const renderer = new THREE.WebGLRenderer({ antialias: true, preserveDrawingBuffer: true });
renderer.setPixelRatio(window.devicePixelRatio);
renderer.shadowMap.enabled = true;
const view = document.getElementById('view');
view.appendChild(renderer.domElement);
const scene = new THREE.Scene();
scene.background = new THREE.Color().setRGB(0.92, 0.94, 0.97, THREE.SRGBColorSpace);  // the video's sky
scene.add(new THREE.HemisphereLight(0xffffff, 0x8090a0, 1.6));
// High, so that a shadow falls nearly straight down, as in the video; its shadow camera spans the
// scene's camera's view.
const sun = new THREE.DirectionalLight(0xffffff, 1.8);
sun.castShadow = true;
sun.shadow.bias = -0.0005;
sun.shadow.normalBias = 0.02;
sun.shadow.mapSize.set(2048, 2048);
const reach = 1.5 * new THREE.Vector3(...run.camera.position).distanceTo(new THREE.Vector3(...run.camera.target));
sun.position.set(run.camera.target[0] + 0.3 * reach, run.camera.target[1] + 2 * reach, run.camera.target[2] + 0.5 * reach);
sun.target.position.set(...run.camera.target);
Object.assign(sun.shadow.camera, { left: -reach, right: reach, top: reach, bottom: -reach, near: 0.1, far: 5 * reach });
scene.add(sun, sun.target);

const camera = new THREE.PerspectiveCamera(run.camera.fov_y_degrees, 16 / 9, 0.05, 2000);
camera.position.set(...run.camera.position);
const controls = new OrbitControls(camera, renderer.domElement);
controls.target.set(...run.camera.target);
controls.update();
controls.addEventListener('change', () => { redraw(); sizeDots(); showLegend(); });

const objects = run.bodies.map((body) => {
  const material = new THREE.MeshStandardMaterial({ color: colourOf(body.colour), roughness: 0.6, metalness: 0.0,
                                                     flatShading: body.shape === 'hull' || body.shape === 'mesh',
                                                     side: body.shape === 'mesh' ? THREE.DoubleSide : THREE.FrontSide });
  const object = body.shape === 'plane' ? planeOf(body, material) : new THREE.Mesh(geometryOf(body), material);
  object.name = body.name;
  if (body.shape !== 'plane') {
    object.castShadow = true;
    object.receiveShadow = true;
    // The sides of a box's or a hull's faces, as the video outlines them (a mesh's where it folds).
    if (body.shape === 'box' || body.shape === 'hull' || body.shape === 'mesh')
      object.add(new THREE.LineSegments(new THREE.EdgesGeometry(object.geometry, body.shape === 'mesh' ? 20 : 5),
                                        new THREE.LineBasicMaterial({ color: 0x2a2d33 })));
  }
  scene.add(object);
  return object;
});

// The video's marks at each frame (run.marks, as the film draws them at the scene's camera):
// arrows (contact normals, impulses, friction, velocities), dots (contact points) and lines (rods,
// ropes), in the video's colours, each frame's as the video shows it. Arrows and lines are solid
// (a shaft and a cone, a thin cylinder); dots keep their size on screen and show through.
const marks = run.marks || null;
const markGroup = new THREE.Group();
scene.add(markGroup);
// Arrows over the bodies, as the video draws them (an impulse starts inside the body it pushes);
// rods among them.
const markMaterials = marks ? marks.palette.map((c) => new THREE.MeshBasicMaterial({ color: colourOf(c), depthTest: false })) : [];
const rodMaterials = marks ? marks.palette.map((c) => new THREE.MeshBasicMaterial({ color: colourOf(c) })) : [];
const unitCylinder = new THREE.CylinderGeometry(1, 1, 1, 12).translate(0, 0.5, 0);  // from y = 0 to 1
const unitCone = new THREE.ConeGeometry(1, 1, 16).translate(0, 0.5, 0);
const dotTexture = (() => {
  const canvas = document.createElement('canvas');
  canvas.width = canvas.height = 64;
  const context = canvas.getContext('2d');
  context.beginPath();
  context.arc(32, 32, 30, 0, 2 * Math.PI);
  context.fillStyle = '#fff';
  context.fill();
  return new THREE.CanvasTexture(canvas);
})();
const pools = { shafts: [], heads: [], rods: [], dots: [] };
function pooled(pool, count, make) {
  while (pool.length < count) {
    const object = make();
    markGroup.add(object);
    pool.push(object);
  }
  pool.forEach((object, i) => { object.visible = i < count; });
  return pool;
}
const up = new THREE.Vector3(0, 1, 0);
// A unit piece (along y from 0 to 1) set from `from` along `along` (not unit), `radius` wide.
function place(object, from, along, length, radius) {
  object.position.copy(from);
  object.quaternion.setFromUnitVectors(up, along.clone().normalize());
  object.scale.set(radius, length, radius);
}
function showMarks(k) {
  if (!marks) return;
  const [arrows, dots, lines] = marks.frames[k];
  const arrowCount = arrows.length / 7;
  const shafts = pooled(pools.shafts, arrowCount, () => new THREE.Mesh(unitCylinder, markMaterials[0]));
  const heads = pooled(pools.heads, arrowCount, () => new THREE.Mesh(unitCone, markMaterials[0]));
  for (let i = 0; i < arrowCount; ++i) {
    const a = arrows.slice(7 * i, 7 * i + 7);
    const from = new THREE.Vector3(a[0], a[1], a[2]), along = new THREE.Vector3(a[3], a[4], a[5]);
    const length = along.length();
    if (length < 1e-6) { shafts[i].visible = heads[i].visible = false; continue; }
    const head = Math.min(0.35 * length, 0.12);
    place(shafts[i], from, along, length - head, Math.min(0.02, 0.1 * length));
    place(heads[i], from.clone().addScaledVector(along, (length - head) / length), along, head, 0.4 * head);
    shafts[i].material = heads[i].material = markMaterials[a[6]];
    shafts[i].renderOrder = heads[i].renderOrder = 1;
    shafts[i].userData.arrow = a;
  }
  const lineCount = lines.length / 8;
  const rods = pooled(pools.rods, lineCount, () => new THREE.Mesh(unitCylinder, markMaterials[0]));
  for (let i = 0; i < lineCount; ++i) {
    const l = lines.slice(8 * i, 8 * i + 8);
    const from = new THREE.Vector3(l[0], l[1], l[2]), to = new THREE.Vector3(l[3], l[4], l[5]);
    const along = to.clone().sub(from);
    place(rods[i], from, along.lengthSq() > 0 ? along : up, along.length(), 0.008);
    rods[i].material = rodMaterials[l[6]];
    rods[i].userData.line = l;
  }
  const dotCount = dots.length / 6;
  const points = pooled(pools.dots, dotCount, () => new THREE.Sprite(new THREE.SpriteMaterial({ map: dotTexture, depthTest: false,
                                                                                                 sizeAttenuation: false })));
  for (let i = 0; i < dotCount; ++i) {
    const d = dots.slice(6 * i, 6 * i + 6);
    points[i].position.set(d[0], d[1], d[2]);
    points[i].material.color.copy(markMaterials[d[3]].color);
    points[i].userData.dot = d;
    points[i].renderOrder = 2;
  }
  sizeDots();
}
// A dot `radius_pixels` across on screen, but no larger than its largest radius where it is.
function sizeDots() {
  const height = Math.max(1, view.clientHeight);
  const metresPerPixel = (distance) => (2 * distance * Math.tan(THREE.MathUtils.degToRad(camera.fov) / 2)) / height;
  for (const sprite of pools.dots) {
    if (!sprite.visible) continue;
    const [, , , , pixels, largest] = sprite.userData.dot;
    const distance = camera.position.distanceTo(sprite.position);
    const radius = largest > 0 ? Math.min(pixels, largest / metresPerPixel(distance)) : pixels;
    // Without attenuation a sprite's scale s spans s / (2 tan(fov/2)) of the view's height.
    sprite.scale.setScalar((2 * radius * 2 * Math.tan(THREE.MathUtils.degToRad(camera.fov) / 2)) / height);
  }
}

// The video's legend for these marks: each arrow entry's round value drawn as long as it is at the
// camera's target now.
const legendBox = document.getElementById('legend');
function showLegend() {
  if (!marks || marks.legend.length === 0) return;
  const height = Math.max(1, view.clientHeight);
  const distance = camera.position.distanceTo(controls.target);
  const pixelsPerMetre = height / (2 * distance * Math.tan(THREE.MathUtils.degToRad(camera.fov) / 2));
  legendBox.replaceChildren();
  for (const entry of marks.legend) {
    const row = document.createElement('div');
    const colour = '#' + colourOf(entry.colour).getHexString(THREE.SRGBColorSpace);
    const svg = document.createElementNS('http://www.w3.org/2000/svg', 'svg');
    const long = entry.dot ? 14 : Math.max(16, Math.min(140, entry.metres * pixelsPerMetre));
    svg.setAttribute('width', String(entry.dot ? 14 : Math.ceil(long) + 2));
    svg.setAttribute('height', '14');
    svg.innerHTML = entry.dot ? `<circle cx="7" cy="7" r="4" fill="${colour}"/>`
      : entry.metres > 0 ? `<path d="M0 7H${long - 7}" stroke="${colour}" stroke-width="3"/><path d="M${long - 8} 2L${long} 7L${long - 8} 12Z" fill="${colour}"/>`
        : `<rect x="0" y="2" width="14" height="10" fill="${colour}"/>`;
    row.append(svg, document.createTextNode(' ' + entry.text));
    legendBox.append(row);
  }
  legendBox.hidden = false;
}

// Every frame's poses, decoded once: the run lists per frame the bodies that moved (index, then
// x y z, w x y z); a body keeps its pose until it is listed again.
const poses = new Float64Array(frameCount * bodyCount * 7);
for (let k = 0; k < frameCount; ++k) {
  const here = k * bodyCount * 7;
  if (k > 0) poses.copyWithin(here, here - bodyCount * 7, here);
  const listed = run.frames[k];
  for (let at = 0; at < listed.length; at += 8) poses.set(listed.slice(at + 1, at + 8), here + 7 * listed[at]);
}

// Drawn again only when something changed: the moment, the camera, the view's size.
let stale = true;
const redraw = () => { stale = true; };

// Every frame's velocity and spin, decoded as the poses are: index, then vx vy vz, wx wy wz.
const motions = new Float64Array(frameCount * bodyCount * 6);
for (let k = 0; k < frameCount; ++k) {
  const here = k * bodyCount * 6;
  if (k > 0) motions.copyWithin(here, here - bodyCount * 6, here);
  const listed = run.motion[k] || [];
  for (let at = 0; at < listed.length; at += 7) motions.set(listed.slice(at + 1, at + 7), here + 6 * listed[at]);
}

function showFrame(k) {
  redraw();
  showMarks(k);
  const here = k * bodyCount * 7;
  for (let i = 0; i < bodyCount; ++i) {
    if (run.bodies[i].shape === 'plane') continue;
    const p = here + 7 * i;
    objects[i].position.set(poses[p], poses[p + 1], poses[p + 2]);
    objects[i].quaternion.set(poses[p + 4], poses[p + 5], poses[p + 6], poses[p + 3]);
  }
}

// A body's numbers at the frame shown, on a click: velocity, spin, momentum, kinetic energy
// (translation + rotation, I in the world's frame) and potential energy (from the origin).
const panel = document.getElementById('panel');
let chosen = -1;
function numbersOf(i, k) {
  const body = run.bodies[i];
  const m = motions.subarray((k * bodyCount + i) * 6, (k * bodyCount + i) * 6 + 6);
  const v = new THREE.Vector3(m[0], m[1], m[2]), w = new THREE.Vector3(m[3], m[4], m[5]);
  const p = (k * bodyCount + i) * 7;
  const position = new THREE.Vector3(poses[p], poses[p + 1], poses[p + 2]);
  const turn = new THREE.Matrix3().setFromMatrix4(new THREE.Matrix4().makeRotationFromQuaternion(
    new THREE.Quaternion(poses[p + 4], poses[p + 5], poses[p + 6], poses[p + 3])));
  const inertia = new THREE.Matrix3().fromArray(body.inertia).transpose();  // row by row in the run
  const worldInertia = turn.clone().multiply(inertia).multiply(turn.clone().transpose());
  const translation = 0.5 * body.mass * v.lengthSq();
  const rotation = 0.5 * w.dot(w.clone().applyMatrix3(worldInertia));
  const potential = -body.mass * new THREE.Vector3(...run.gravity).dot(position);
  return { velocity: v, spin: w, momentum: v.clone().multiplyScalar(body.mass), translation, rotation, potential };
}
function showPanel() {
  objects.forEach((object, i) => { if (object.material.emissive) object.material.emissive.setHex(i === chosen ? 0x303030 : 0x000000); });
  redraw();
  if (chosen < 0) {
    panel.hidden = true;
    return;
  }
  const body = run.bodies[chosen];
  const n = numbersOf(chosen, frame);
  const f = (x) => x.toFixed(3);
  const vector = (u) => '(' + f(u.x) + ', ' + f(u.y) + ', ' + f(u.z) + ')';
  const rows = [
    ['v', vector(n.velocity) + ' m/s'],
    ['|v|', f(n.velocity.length()) + ' m/s'],
    ['\u03c9', vector(n.spin) + ' rad/s'],
    ['p = m v', vector(n.momentum) + ' kg\u00b7m/s'],
    ['kinetic', f(n.translation + n.rotation) + ' J = ' + f(n.translation) + ' + ' + f(n.rotation)],
    ['potential', f(n.potential) + ' J'],
  ];
  panel.replaceChildren();
  const title = document.createElement('h2');
  title.textContent = body.name + ', t = ' + (frame / run.fps).toFixed(2) + ' s';
  panel.append(title);
  const table = document.createElement('table');
  for (const row of rows) {
    const tr = table.insertRow();
    for (const cell of row) tr.insertCell().textContent = cell;
  }
  panel.append(table);
  const note = document.createElement('p');
  note.textContent = 'm = ' + f(body.mass) + ' kg; kinetic = \u00bd m v\u00b2 + \u00bd \u03c9\u00b7I\u03c9; potential = \u2212m g\u00b7x';
  panel.append(note);
  const numbers = (u) => [u.x, u.y, u.z].join(' ');
  Object.assign(panel.dataset, { body: body.name, time: String(frame / run.fps), velocity: numbers(n.velocity), spin: numbers(n.spin),
                                  momentum: numbers(n.momentum), kinetic: String(n.translation + n.rotation), potential: String(n.potential) });
  panel.hidden = false;
}
// A click (not a drag: that orbits) on a moving body chooses it; elsewhere, none.
const raycaster = new THREE.Raycaster();
let pressed = null;
renderer.domElement.addEventListener('pointerdown', (event) => { pressed = [event.clientX, event.clientY]; });
renderer.domElement.addEventListener('pointerup', (event) => {
  if (!pressed || Math.hypot(event.clientX - pressed[0], event.clientY - pressed[1]) > 4) return;
  const box = renderer.domElement.getBoundingClientRect();
  scene.updateMatrixWorld();  // the poses of the frame shown, drawn yet or not
  raycaster.setFromCamera(new THREE.Vector2(((event.clientX - box.left) / box.width) * 2 - 1,
                                            -((event.clientY - box.top) / box.height) * 2 + 1), camera);
  const movable = objects.filter((object, i) => !run.bodies[i].static);
  const hit = raycaster.intersectObjects(movable, false)[0];
  chosen = hit ? objects.indexOf(hit.object) : -1;
  showPanel();
});

const slider = document.getElementById('time');
const clock = document.getElementById('clock');
const playButton = document.getElementById('play');
const speed = document.getElementById('speed');
slider.max = String(frameCount - 1);
let frame = 0;
let playing = false;
let shownTime = 0;  // s of simulated time played to
let lastTick = 0;   // ms: when it was
// Simulated s per s of playing at a frame: the video's (slower around impacts), times the chosen.
const rateAt = (k) => (run.speeds ? run.speeds[Math.max(0, Math.min(frameCount - 1, k))] : 1) * Number(speed.value);
const slowAt = (k) => run.speeds && run.speeds[k] < 0.999 * run.playback_speed;
// Plays on by `seconds` of real time, at each moment's rate (a tenth of a frame at a time).
function advance(seconds) {
  let left = seconds;
  while (left > 0 && shownTime < (frameCount - 1) / run.fps) {
    const piece = Math.min(left, 0.1 / run.fps / Math.max(rateAt(Math.floor(shownTime * run.fps + 1e-9)), 1e-3));
    shownTime += piece * rateAt(Math.floor(shownTime * run.fps + 1e-9));
    left -= piece;
  }
  return shownTime;
}
const caption = document.getElementById('caption');
function setFrame(k) {
  frame = Math.max(0, Math.min(frameCount - 1, k));
  slider.value = String(frame);
  const time = frame / run.fps;
  clock.textContent = 't = ' + time.toFixed(2) + ' s' + (slowAt(frame) ? '  slow motion \u00d7' + (run.speeds[frame] / run.playback_speed).toFixed(2) : '');
  const shown = run.captions.find((c) => c.start <= time && time < c.end);
  caption.textContent = shown ? shown.text : '';
  showFrame(frame);
  if (chosen >= 0) showPanel();
}
function play(on) {
  playing = on;
  playButton.textContent = on ? 'Pause' : 'Play';
  if (on) {
    if (frame >= frameCount - 1) setFrame(0);
    shownTime = frame / run.fps;
    lastTick = performance.now();
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
  sizeDots();
  showLegend();
  redraw();
}
window.addEventListener('resize', resize);
resize();

renderer.setAnimationLoop(() => {
  if (playing) {
    const now = performance.now();
    advance((now - lastTick) / 1000);
    lastTick = now;
    const k = Math.floor(shownTime * run.fps + 1e-9);
    if (k >= frameCount - 1) { setFrame(frameCount - 1); play(false); } else if (k !== frame) setFrame(k);
  }
  if (stale) {
    stale = false;
    renderer.render(scene, camera);
  }
});
setFrame(0);

// The test hook: the drawn poses (each object's world matrix) at the frames of the asked moments,
// and where each centre falls in the view (pixels from its top left); `&size=854x480` hides the
// controls and makes the view that size, as the video's frame is.
const probe = /#probe=([0-9.,]+)/.exec(window.location.hash);
if (probe) {
  const size = /&size=(\d+)x(\d+)/.exec(window.location.hash);
  if (size) {
    document.body.classList.add('bare');
    view.style.width = size[1] + 'px';
    view.style.height = size[2] + 'px';
    resize();
  }
  const lines = ['VIEW ' + view.clientWidth + ' ' + view.clientHeight];
  for (const text of probe[1].split(',')) {
    const k = Math.round(Number(text) * run.fps);
    setFrame(k);
    scene.updateMatrixWorld(true);
    camera.updateMatrixWorld(true);  // not in the scene: render() would, but nothing has rendered yet
    objects.forEach((object, i) => {
      if (run.bodies[i].shape === 'plane') return;
      const position = new THREE.Vector3(), rotation = new THREE.Quaternion(), scale = new THREE.Vector3();
      object.matrixWorld.decompose(position, rotation, scale);
      lines.push(['POSE', (k / run.fps).toFixed(6), position.x, position.y, position.z, rotation.w, rotation.x, rotation.y, rotation.z, run.bodies[i].name].join(' '));
      const seen = position.clone().project(camera);
      lines.push(['PIXEL', (k / run.fps).toFixed(6), (seen.x + 1) / 2 * view.clientWidth, (1 - seen.y) / 2 * view.clientHeight, run.bodies[i].name].join(' '));
    });
    // The marks as drawn: each arrow's origin and vector (shaft and head together), each line's
    // ends, each dot's place, with their colours (sRGB).
    const time = (k / run.fps).toFixed(6);
    const hex = (material) => '#' + material.color.getHexString(THREE.SRGBColorSpace);
    pools.shafts.forEach((shaft, i) => {
      if (!shaft.visible) return;
      const head = pools.heads[i];
      const along = up.clone().applyQuaternion(shaft.quaternion).multiplyScalar(shaft.scale.y + head.scale.y);
      lines.push(['ARROW', time, shaft.position.x, shaft.position.y, shaft.position.z, along.x, along.y, along.z, hex(shaft.material)].join(' '));
    });
    pools.rods.forEach((rod) => {
      if (!rod.visible) return;
      const to = up.clone().applyQuaternion(rod.quaternion).multiplyScalar(rod.scale.y).add(rod.position);
      lines.push(['LINE', time, rod.position.x, rod.position.y, rod.position.z, to.x, to.y, to.z, hex(rod.material)].join(' '));
    });
    pools.dots.forEach((dot) => {
      if (dot.visible) lines.push(['DOT', time, dot.position.x, dot.position.y, dot.position.z, hex(dot.material)].join(' '));
    });
  }
  renderer.render(scene, camera);
  lines.push('GL ' + (renderer.getContext() ? 'yes' : 'no'));
  document.getElementById('probe').textContent = lines.join('\n');
}
// The preview's page (impulse preview serves it with its state in #impulse-live): polls /state,
// reloads when a new run has been made, keeping the camera, the moment and whether it plays, and
// shows the scene's error over the last good run.
const liveBlock = document.getElementById('impulse-live');
const version = liveBlock ? JSON.parse(liveBlock.textContent).version : null;
if (liveBlock) {
  const problem = document.getElementById('problem');
  const keptKey = 'impulse-preview-view';
  const kept = JSON.parse(sessionStorage.getItem(keptKey) || 'null');
  if (kept) {
    camera.position.fromArray(kept.position);
    controls.target.fromArray(kept.target);
    controls.update();
    setFrame(Math.round(kept.time * run.fps));
    if (kept.playing) play(true);
  }
  const show = (state) => {
    problem.textContent = state.error ? state.error + '\n(the page shows the last run that read: mend the file and save it)' : '';
  };
  show(JSON.parse(liveBlock.textContent));
  const poll = async () => {
    let wait = 250;
    try {
      const state = await (await fetch('state', { cache: 'no-store' })).json();
      if (state.version !== version && !state.error && !state.busy) {
        sessionStorage.setItem(keptKey, JSON.stringify({ position: camera.position.toArray(), target: controls.target.toArray(),
                                                         time: frame / run.fps, playing }));
        window.location.reload();
        return;
      }
      show(state);
    } catch (failure) {
      problem.textContent = 'The preview has stopped: run impulse preview again, then reload this page.';
      wait = 1000;
    }
    setTimeout(poll, wait);
  };
  setTimeout(poll, 250);
}
// Where a body's centre falls in the page (CSS pixels from its top left), for a test's click.
function pixelOf(name) {
  const object = objects[run.bodies.findIndex((body) => body.name === name)];
  camera.updateMatrixWorld(true);
  const seen = object.position.clone().project(camera);
  const box = renderer.domElement.getBoundingClientRect();
  return [box.left + ((seen.x + 1) / 2) * box.width, box.top + ((1 - seen.y) / 2) * box.height];
}
// `advance` for a test: from frame k, how far `seconds` of playing take the simulated time.
const playedFrom = (k, seconds) => { shownTime = k / run.fps; return advance(seconds); };
window.impulsePage = { run, frameCount, setFrame, errors, camera, controls, version, frame: () => frame, pixelOf, playedFrom };
