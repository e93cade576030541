// The interactive page of a scene (impulse export): the bodies of the scene's run, drawn with
// three.js at each video frame's poses, played, paused, scrubbed and orbited; a comparison's panes
// side by side, one camera for all. The program writes the run into the page as JSON, gzipped, in
// base64 (<script id="impulse-run">, demos/page/); nothing is fetched. Test hook:
// #probe=T1,T2 writes each body's drawn pose at those moments into <pre id="probe">, and every
// error into <pre id="errors">.
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

// The run, as the program packs it: JSON, gzipped, in base64.
async function unpackedRun() {
  const text = document.getElementById('impulse-run').textContent.trim();
  const bytes = Uint8Array.from(atob(text), (c) => c.charCodeAt(0));
  const stream = new Blob([bytes]).stream().pipeThrough(new DecompressionStream('gzip'));
  return JSON.parse(await new Response(stream).text());
}

function start(run) {
  // Each pane's run: its bodies, frames, motion, marks and equations (one pane: the run itself).
  const paneRuns = run.panes || [run];
  document.getElementById('title').textContent = run.title;
  document.title = run.title + ' \u2014 impulse';
  const frameCount = run.frames ? run.frames.length : paneRuns[0].frames.length;

  // sRGB colours as the video draws them.
  const colourOf = (c) => new THREE.Color().setRGB(c[0], c[1], c[2], THREE.SRGBColorSpace);
  const cssOf = (c) => '#' + colourOf(c).getHexString(THREE.SRGBColorSpace);

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
  function planeOf(body, material, scene) {
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
  renderer.setScissorTest(true);
  const view = document.getElementById('view');
  view.prepend(renderer.domElement);
  const sky = new THREE.Color().setRGB(0.92, 0.94, 0.97, THREE.SRGBColorSpace);  // the video's

  const camera = new THREE.PerspectiveCamera(run.camera.fov_y_degrees, 16 / 9, 0.05, 2000);
  camera.position.set(...run.camera.position);
  const controls = new OrbitControls(camera, renderer.domElement);
  controls.target.set(...run.camera.target);
  controls.update();
  controls.addEventListener('change', () => { redraw(); sizeDots(); showLegend(); });

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
  const up = new THREE.Vector3(0, 1, 0);
  // A unit piece (along y from 0 to 1) set from `from` along `along` (not unit), `radius` wide.
  function place(object, from, along, length, radius) {
    object.position.copy(from);
    object.quaternion.setFromUnitVectors(up, along.clone().normalize());
    object.scale.set(radius, length, radius);
  }

  // Every frame's numbers of a pane, decoded once: the run lists per frame the bodies whose numbers
  // changed, each as its index, then the change of each number since the body was last listed, in
  // units (1 / `per_unit`); a body keeps its numbers until it is listed again.
  function decoded(listedFrames, bodyCount, perUnit) {
    const width = perUnit.length;
    const all = new Float64Array(frameCount * bodyCount * width);
    const units = new Float64Array(bodyCount * width);  // whole numbers: sums are exact
    for (let k = 0; k < frameCount; ++k) {
      const here = k * bodyCount * width;
      if (k > 0) all.copyWithin(here, here - bodyCount * width, here);
      const listed = listedFrames[k] || [];
      for (let at = 0; at < listed.length; at += width + 1) {
        const i = listed[at];
        for (let c = 0; c < width; ++c) {
          units[i * width + c] += listed[at + 1 + c];
          all[here + i * width + c] = units[i * width + c] / perUnit[c];
        }
      }
    }
    return all;
  }

  // One pane: its own three.js scene (sky, light, bodies, marks), drawn into its rectangle of the
  // view (`rect`, CSS pixels from the view's top left) by the one camera.
  function makePane(paneRun, index) {
    const pane = { run: paneRun, index, rect: { x: 0, y: 0, width: 1, height: 1 }, bodyCount: paneRun.bodies.length };
    const scene = new THREE.Scene();
    pane.scene = scene;
    scene.background = sky;
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

    pane.objects = paneRun.bodies.map((body) => {
      const material = new THREE.MeshStandardMaterial({ color: colourOf(body.colour), roughness: 0.6, metalness: 0.0,
                                                         flatShading: body.shape === 'hull' || body.shape === 'mesh',
                                                         side: body.shape === 'mesh' ? THREE.DoubleSide : THREE.FrontSide });
      const object = body.shape === 'plane' ? planeOf(body, material, scene) : new THREE.Mesh(geometryOf(body), material);
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
    pane.poses = decoded(paneRun.frames, pane.bodyCount, [1e5, 1e5, 1e5, 1e6, 1e6, 1e6, 1e6]);  // x y z (m), w x y z
    pane.motions = decoded(paneRun.motion, pane.bodyCount, [1e4, 1e4, 1e4, 1e4, 1e4, 1e4]);  // v, ω after the frame's last step

    // The video's marks at each frame (marks, as the film draws them at the scene's camera): arrows
    // (contact normals, impulses, friction, velocities) over the bodies, as the video draws them (an
    // impulse starts inside the body it pushes), a shaft and a cone; dots (contact points) that keep
    // their size on screen and show through; lines (rods, ropes), thin cylinders among the bodies.
    const marks = paneRun.marks || null;
    pane.marks = marks;
    const markGroup = new THREE.Group();
    scene.add(markGroup);
    const markMaterials = marks ? marks.palette.map((c) => new THREE.MeshBasicMaterial({ color: colourOf(c), depthTest: false })) : [];
    const rodMaterials = marks ? marks.palette.map((c) => new THREE.MeshBasicMaterial({ color: colourOf(c) })) : [];
    pane.pools = { shafts: [], heads: [], rods: [], dots: [] };
    function pooled(pool, count, make) {
      while (pool.length < count) {
        const object = make();
        markGroup.add(object);
        pool.push(object);
      }
      pool.forEach((object, i) => { object.visible = i < count; });
      return pool;
    }
    pane.showMarks = (k) => {
      if (!marks) return;
      const [arrows, dots, lines] = marks.frames[k];
      const arrowCount = arrows.length / 7;
      const shafts = pooled(pane.pools.shafts, arrowCount, () => new THREE.Mesh(unitCylinder, markMaterials[0]));
      const heads = pooled(pane.pools.heads, arrowCount, () => new THREE.Mesh(unitCone, markMaterials[0]));
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
      }
      const lineCount = lines.length / 8;
      const rods = pooled(pane.pools.rods, lineCount, () => new THREE.Mesh(unitCylinder, markMaterials[0]));
      for (let i = 0; i < lineCount; ++i) {
        const l = lines.slice(8 * i, 8 * i + 8);
        const from = new THREE.Vector3(l[0], l[1], l[2]), to = new THREE.Vector3(l[3], l[4], l[5]);
        const along = to.clone().sub(from);
        place(rods[i], from, along.lengthSq() > 0 ? along : up, along.length(), 0.008);
        rods[i].material = rodMaterials[l[6]];
      }
      const dotCount = dots.length / 6;
      const points = pooled(pane.pools.dots, dotCount, () => new THREE.Sprite(new THREE.SpriteMaterial({ map: dotTexture, depthTest: false,
                                                                                                          sizeAttenuation: false })));
      for (let i = 0; i < dotCount; ++i) {
        const d = dots.slice(6 * i, 6 * i + 6);
        points[i].position.set(d[0], d[1], d[2]);
        points[i].material.color.copy(markMaterials[d[3]].color);
        points[i].userData.dot = d;
        points[i].renderOrder = 2;
      }
    };
    pane.showFrame = (k) => {
      pane.showMarks(k);
      const here = k * pane.bodyCount * 7;
      for (let i = 0; i < pane.bodyCount; ++i) {
        if (paneRun.bodies[i].shape === 'plane') continue;
        const p = here + 7 * i;
        pane.objects[i].position.set(pane.poses[p], pane.poses[p + 1], pane.poses[p + 2]);
        pane.objects[i].quaternion.set(pane.poses[p + 4], pane.poses[p + 5], pane.poses[p + 6], pane.poses[p + 3]);
      }
    };

    // Its box over the view: corners for its equations, its own caption, and (in a comparison) its
    // label, bottom left in its colour, as the video's.
    pane.box = document.createElement('div');
    pane.box.className = 'pane';
    pane.corners = makeCorners(pane.box);
    if (paneRun.label) {
      const label = document.createElement('div');
      label.className = 'label';
      label.textContent = paneRun.label;
      label.style.color = cssOf(paneRun.colour);
      label.style.borderColor = cssOf(paneRun.colour);
      pane.corners['bottom-left'].after(label);
    }
    pane.caption = document.createElement('div');
    pane.caption.className = 'caption';
    pane.corners.bottom.append(pane.caption);
    return pane;
  }

  // Places for equation panels in a box, as the video's painter stacks them.
  function makeCorners(box) {
    const corners = {};
    for (const where of ['top-left', 'top-right', 'bottom-left', 'bottom-right', 'bottom']) {
      corners[where] = document.createElement('div');
      corners[where].className = 'corner ' + where;
      box.append(corners[where]);
    }
    return corners;
  }

  const overlay = document.getElementById('overlay');
  const panes = paneRuns.map(makePane);
  const whole = makeCorners(overlay);  // the view's own: panels every pane shows alike
  if (panes.length === 1) {
    // One scene: its box is the view's, its caption the page's.
    panes[0].box.remove();
    panes[0].corners = whole;
    panes[0].caption = document.getElementById('caption');
  } else {
    for (const pane of panes) overlay.append(pane.box);
  }
  whole.bottom.append(document.getElementById('caption'));
  whole['bottom-left'].append(document.getElementById('legend'));
  whole['top-right'].append(document.getElementById('panel'));

  // Where the panes go in the view: one fills it; two side by side, each of the video's shape; three
  // or four in a grid of two columns, each 1.2 to 2.4 times as wide as high (a camera's field of view
  // is vertical); under the title, over a band for the legend and the captions. `exact`: each pane
  // exactly that size, edge to edge.
  function layOut(width, height, exact) {
    if (panes.length === 1) {
      panes[0].rect = { x: 0, y: 0, width, height };
      return;
    }
    // The plots, as the video's: in a row under one row of panes, in a column beside two.
    const columns = 2, rows = Math.ceil(panes.length / 2);
    const plotted = run.plots && !exact;
    const [top, band, gap] = exact ? [0, 0, 0] : [64, 116, 8];
    const plotsBand = plotted && rows === 1 ? plotHeight + 40 : 0, plotsColumn = plotted && rows > 1 ? plotWidth + 20 + 2 * gap : 0;  // 20: its padding
    const roomWidth = width - plotsColumn - (columns + 1) * gap, roomHeight = height - top - band - plotsBand - rows * gap;
    let paneWidth, paneHeight;
    if (exact) {
      [paneWidth, paneHeight] = exact;
    } else if (rows === 1) {
      paneWidth = Math.min(roomWidth / 2, (roomHeight * 16) / 9);
      paneHeight = (paneWidth * 9) / 16;
    } else {
      paneWidth = Math.min(roomWidth / 2, (2.4 * roomHeight) / 2);
      paneHeight = Math.min(roomHeight / 2, roomWidth / 2 / 1.2);
    }
    paneWidth = Math.max(1, Math.floor(paneWidth));
    paneHeight = Math.max(1, Math.floor(paneHeight));
    const left = Math.round((width - plotsColumn - columns * paneWidth - (columns - 1) * gap) / 2);
    const blockHeight = rows * paneHeight + (rows - 1) * gap + plotsBand;
    const upper = top + Math.max(0, Math.round((height - top - band - blockHeight) / 2));
    panes.forEach((pane, i) => {
      pane.rect = { x: left + (i % columns) * (paneWidth + gap), y: upper + Math.floor(i / columns) * (paneHeight + gap),
                    width: paneWidth, height: paneHeight };
      Object.assign(pane.box.style, { left: pane.rect.x + 'px', top: pane.rect.y + 'px', width: pane.rect.width + 'px', height: pane.rect.height + 'px' });
    });
    if (plotted) {
      overlay.append(plotBox);
      Object.assign(plotBox.style, rows === 1 ? { position: 'absolute', flexDirection: 'row', left: left + 'px', top: upper + paneHeight + gap + 'px' }
        : { position: 'absolute', right: gap + 'px', top: upper + 'px' });
    }
  }

  // A dot `radius_pixels` across on screen, but no larger than its largest radius where it is.
  function sizeDots() {
    for (const pane of panes) {
      const height = Math.max(1, pane.rect.height);
      const metresPerPixel = (distance) => (2 * distance * Math.tan(THREE.MathUtils.degToRad(camera.fov) / 2)) / height;
      for (const sprite of pane.pools.dots) {
        if (!sprite.visible) continue;
        const [, , , , pixels, largest] = sprite.userData.dot;
        const distance = camera.position.distanceTo(sprite.position);
        const radius = largest > 0 ? Math.min(pixels, largest / metresPerPixel(distance)) : pixels;
        // Without attenuation a sprite's scale s spans s / (2 tan(fov/2)) of the view's height.
        sprite.scale.setScalar((2 * radius * 2 * Math.tan(THREE.MathUtils.degToRad(camera.fov) / 2)) / height);
      }
    }
  }

  // The video's legend for these marks (one scale for every pane): each arrow entry's round value
  // drawn as long as it is at the camera's target now.
  const legendBox = document.getElementById('legend');
  const legendEntries = paneRuns[0].marks ? paneRuns[0].marks.legend : [];
  function showLegend() {
    if (legendEntries.length === 0) return;
    const height = Math.max(1, panes[0].rect.height);
    const distance = camera.position.distanceTo(controls.target);
    const pixelsPerMetre = height / (2 * distance * Math.tan(THREE.MathUtils.degToRad(camera.fov) / 2));
    legendBox.replaceChildren();
    for (const entry of legendEntries) {
      const row = document.createElement('div');
      const colour = cssOf(entry.colour);
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
    clearBottom();
  }

  // The typeset equations (run.panels, run.svgs: each [[equation]] and the [overlay] equation panel
  // with the latest impact's numbers, as the film sets them with LaTeX): per frame each pane's, as
  // [panel, opacity, ...]; what every pane shows alike is shown once, for the view. Sized as in the
  // video: the SVG's TeX points times the panel's scale at 720 lines of the view.
  const panelElements = new Map();  // by panel index
  function panelElement(i) {
    if (panelElements.has(i)) return panelElements.get(i);
    const entry = run.panels[i];
    const element = document.createElement('div');
    element.className = 'equation';
    for (const line of entry.lines) {
      const heading = document.createElement('div');
      heading.textContent = line;
      heading.style.color = cssOf(entry.colour);
      element.append(heading);
    }
    const svg = run.svgs[entry.svg];
    const image = document.createElement('img');
    image.alt = 'typeset equation';
    image.src = 'data:image/svg+xml;charset=utf-8,' + encodeURIComponent(svg);
    const width = /width=['"]([0-9.]+)pt['"]/.exec(svg);
    image.dataset.points = width ? width[1] : '100';
    image.dataset.scale = String(entry.scale);
    element.append(image);
    element.dataset.panel = String(i);
    panelElements.set(i, element);
    return element;
  }
  function sizePanels() {
    const linesHigh = Math.max(1, view.clientHeight) / 720;
    for (const element of panelElements.values()) {
      const image = element.querySelector('img');
      image.style.width = (Number(image.dataset.points) * Number(image.dataset.scale) * linesHigh).toFixed(1) + 'px';
    }
    clearBottom();
  }
  // The caption between what the bottom corners hold, or above them where that leaves it too little.
  function clearBottom() {
    const wide = (corner) => (corner.childElementCount && corner.offsetWidth ? corner.offsetWidth + 24 : 0);
    const high = (corner) => (corner.childElementCount && corner.offsetHeight ? corner.offsetHeight + 8 : 0);
    const left = wide(whole['bottom-left']), right = wide(whole['bottom-right']);
    const room = view.clientWidth - 2 * Math.max(left, right) - 32;
    const above = room < 360;
    Object.assign(whole.bottom.style, { width: (above ? 0.8 * view.clientWidth : Math.min(0.8 * view.clientWidth, room)) + 'px',
                                        bottom: (above ? 16 + Math.max(high(whole['bottom-left']), high(whole['bottom-right'])) : 16) + 'px' });
  }
  let shownPanels = '';
  function showPanels(k) {
    if (!run.panels) return;
    const lists = panes.map((pane) => (pane.run.panel_frames ? pane.run.panel_frames[k] : []));
    const key = JSON.stringify(lists);
    if (key === shownPanels) return;
    shownPanels = key;
    for (const element of panelElements.values()) element.remove();
    const sameEverywhere = (i, opacity) => panes.length > 1 &&
      lists.every((list) => list.some((v, at) => at % 2 === 0 && v === i && list[at + 1] === opacity));
    lists.forEach((list, p) => {
      for (let at = 0; at < list.length; at += 2) {
        const [i, opacity] = [list[at], list[at + 1]];
        const shared = sameEverywhere(i, opacity);
        if (shared && p > 0) continue;
        const element = panelElement(i);
        element.style.opacity = String(opacity);
        const corner = run.panels[i].place === 'corner' ? 'top-right' : run.panels[i].place;
        const corners = shared ? whole : panes[p].corners;
        if (corner === 'bottom' || corner.startsWith('bottom-')) corners[corner].prepend(element); else corners[corner].append(element);
      }
    });
    sizePanels();
  }

  // The video's live plots (run.plots: every curve of the whole run, on the run's axes): each drawn
  // up to the moment shown, its latest value in the heading in its colour.
  const svgNamespace = 'http://www.w3.org/2000/svg';
  const plotBox = document.createElement('div');
  plotBox.id = 'plots';
  if (run.plots) whole['top-right'].prepend(plotBox);
  const plotWidth = 260, plotHeight = 84;
  const plots = (run.plots || []).map((plot) => {
    const element = document.createElement('div');
    element.className = 'plot';
    element.style.width = plotWidth + 'px';  // a long heading wraps
    const heading = document.createElement('div');
    const svg = document.createElementNS(svgNamespace, 'svg');
    svg.setAttribute('width', String(plotWidth));
    svg.setAttribute('height', String(plotHeight));
    svg.innerHTML = `<path d="M0.5 0.5V${plotHeight - 0.5}H${plotWidth - 0.5}" fill="none" stroke="#8a8f99"/>`;
    let top = plot.y_max, bottom = plot.y_min;
    if (!(top > bottom)) {  // no fixed range: the points'
      const values = plot.series.flatMap((series) => series.points.filter((v, at) => at % 2 === 1));
      top = Math.max(bottom + 1e-9, ...values);
    }
    const curves = plot.series.map((series) => {
      const line = document.createElementNS(svgNamespace, 'polyline');
      Object.entries({ fill: 'none', stroke: cssOf(series.colour), 'stroke-width': '2', 'stroke-linejoin': 'round' })
        .forEach(([name, value]) => line.setAttribute(name, value));
      svg.append(line);
      const times = [], values = [], pixels = [];
      for (let at = 0; at < series.points.length; at += 2) {
        const [t, v] = [series.points[at], series.points[at + 1]];
        times.push(t);
        values.push(v);
        pixels.push(((1 + ((t - plot.x_start) / (plot.x_end - plot.x_start)) * (plotWidth - 2)).toFixed(1) + ',' +
                     (plotHeight - 1 - ((v - bottom) / (top - bottom)) * (plotHeight - 4)).toFixed(1)));
      }
      return { line, times, values, pixels, colour: cssOf(series.colour), shown: -1 };
    });
    element.append(heading, svg);
    plotBox.append(element);
    return { plot, heading, curves };
  });
  function showPlots(time) {
    for (const { plot, heading, curves } of plots) {
      const latest = [];
      for (const curve of curves) {
        let n = 0, high = curve.times.length;  // the points at or before `time`
        while (n < high) {
          const middle = (n + high) >> 1;
          if (curve.times[middle] <= time + 6e-5) n = middle + 1; else high = middle;  // times to 1e-4 s
        }
        if (n !== curve.shown) {
          curve.line.setAttribute('points', curve.pixels.slice(0, n).join(' '));
          curve.shown = n;
        }
        if (n > 0) latest.push([curve.values[n - 1], curve.colour]);
      }
      heading.replaceChildren(plot.title + (latest.length ? ': ' : ''));
      latest.forEach(([value, colour], i) => {
        const number = document.createElement('span');
        number.style.color = colour;
        number.textContent = (i > 0 ? ', ' : '') + value.toFixed(2);
        heading.append(number);
      });
      heading.append(' ' + plot.unit);
    }
  }

  // Drawn again only when something changed: the moment, the camera, the view's size.
  let stale = true;
  const redraw = () => { stale = true; };

  // A body's numbers at the frame shown, on a click: velocity, spin, momentum, kinetic energy
  // (translation + rotation, I in the world's frame) and potential energy (from the origin).
  const panel = document.getElementById('panel');
  let chosen = null;  // { pane, body }
  function numbersOf(pane, i, k) {
    const body = pane.run.bodies[i];
    const at = k * pane.bodyCount + i;
    const m = pane.motions.subarray(at * 6, at * 6 + 6);
    const v = new THREE.Vector3(m[0], m[1], m[2]), w = new THREE.Vector3(m[3], m[4], m[5]);
    const p = at * 7, poses = pane.poses;
    const position = new THREE.Vector3(poses[p], poses[p + 1], poses[p + 2]);
    const turn = new THREE.Matrix3().setFromMatrix4(new THREE.Matrix4().makeRotationFromQuaternion(
      new THREE.Quaternion(poses[p + 4], poses[p + 5], poses[p + 6], poses[p + 3])));
    const inertia = new THREE.Matrix3().fromArray(body.inertia).transpose();  // row by row in the run
    const worldInertia = turn.clone().multiply(inertia).multiply(turn.clone().transpose());
    const translation = 0.5 * body.mass * v.lengthSq();
    const rotation = 0.5 * w.dot(w.clone().applyMatrix3(worldInertia));
    const potential = -body.mass * new THREE.Vector3(...pane.run.gravity).dot(position);
    return { velocity: v, spin: w, momentum: v.clone().multiplyScalar(body.mass), translation, rotation, potential };
  }
  function showPanel() {
    for (const pane of panes)
      pane.objects.forEach((object, i) => {
        if (object.material.emissive) object.material.emissive.setHex(chosen && chosen.pane === pane && i === chosen.body ? 0x303030 : 0x000000);
      });
    redraw();
    if (!chosen) {
      panel.hidden = true;
      return;
    }
    const body = chosen.pane.run.bodies[chosen.body];
    const n = numbersOf(chosen.pane, chosen.body, frame);
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
    title.textContent = body.name + (chosen.pane.run.label ? ' (' + chosen.pane.run.label + ')' : '') + ', t = ' + (frame / run.fps).toFixed(2) + ' s';
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
    Object.assign(panel.dataset, { body: body.name, pane: String(chosen.pane.index + 1), time: String(frame / run.fps),
                                    velocity: numbers(n.velocity), spin: numbers(n.spin), momentum: numbers(n.momentum),
                                    kinetic: String(n.translation + n.rotation), potential: String(n.potential) });
    panel.hidden = false;
  }
  // The pane under a point of the canvas (CSS pixels from its top left), and the point in its
  // normalised coordinates.
  function paneAt(x, y) {
    const pane = panes.find((p) => x >= p.rect.x && x < p.rect.x + p.rect.width && y >= p.rect.y && y < p.rect.y + p.rect.height);
    return pane ? { pane, ndc: new THREE.Vector2(((x - pane.rect.x) / pane.rect.width) * 2 - 1, -((y - pane.rect.y) / pane.rect.height) * 2 + 1) } : null;
  }
  // A click (not a drag: that orbits) on a moving body chooses it; elsewhere, none.
  const raycaster = new THREE.Raycaster();
  let pressed = null;
  renderer.domElement.addEventListener('pointerdown', (event) => { pressed = [event.clientX, event.clientY]; });
  renderer.domElement.addEventListener('pointerup', (event) => {
    if (!pressed || Math.hypot(event.clientX - pressed[0], event.clientY - pressed[1]) > 4) return;
    const box = renderer.domElement.getBoundingClientRect();
    const under = paneAt(event.clientX - box.left, event.clientY - box.top);
    chosen = null;
    if (under) {
      const { pane, ndc } = under;
      setAspect(pane);
      pane.scene.updateMatrixWorld();  // the poses of the frame shown, drawn yet or not
      raycaster.setFromCamera(ndc, camera);
      const movable = pane.objects.filter((object, i) => !pane.run.bodies[i].static);
      const hit = raycaster.intersectObjects(movable, false)[0];
      if (hit) chosen = { pane, body: pane.objects.indexOf(hit.object) };
    }
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
  const shownCaption = (captions, time) => (captions || []).find((c) => c.start <= time && time < c.end);
  // The video's camera where it moves ([camera] follow, keyframes, fit): followed frame by frame
  // until the viewer orbits, zooms or pans; the box in the bar takes it back.
  const path = run.camera_path || null;
  const follow = document.createElement('input');
  if (path) {
    follow.type = 'checkbox';
    follow.id = 'follow';
    follow.checked = true;
    const label = document.createElement('label');
    label.append(follow, ' video\u2019s camera');
    speed.parentElement.before(label);
    controls.addEventListener('start', () => { follow.checked = false; });
    follow.addEventListener('change', () => followPath());
  }
  function followPath() {
    if (!path || !follow.checked) return;
    const c = path[frame];
    camera.position.set(c[0], c[1], c[2]);
    controls.target.set(c[3], c[4], c[5]);
    if (camera.fov !== c[6]) {
      camera.fov = c[6];
      camera.updateProjectionMatrix();
    }
    controls.update();
    sizeDots();
    showLegend();
    redraw();
  }
  function setFrame(k) {
    frame = Math.max(0, Math.min(frameCount - 1, k));
    followPath();
    slider.value = String(frame);
    const time = frame / run.fps;
    clock.textContent = 't = ' + time.toFixed(2) + ' s' + (slowAt(frame) ? '  slow motion \u00d7' + (run.speeds[frame] / run.playback_speed).toFixed(2) : '');
    const caption = shownCaption(run.captions, time);
    document.getElementById('caption').textContent = caption ? caption.text : '';
    for (const pane of panes) {
      if (panes.length > 1) {
        const own = shownCaption(pane.run.captions, time);
        pane.caption.textContent = own ? own.text : '';
      }
      pane.showFrame(frame);
    }
    showPanels(frame);
    showPlots(time);
    sizeDots();
    redraw();
    if (chosen) showPanel();
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

  let exactPanes = null;  // the probe's pane size
  function resize() {
    const width = view.clientWidth, height = view.clientHeight;
    renderer.setSize(width, height, false);
    layOut(width, height, exactPanes);
    setAspect(panes[0]);
    sizeDots();
    showLegend();
    sizePanels();
    redraw();
  }
  // The camera's shape for a pane (all panes are alike).
  function setAspect(pane) {
    const aspect = pane.rect.width / Math.max(1, pane.rect.height);
    if (camera.aspect !== aspect) {
      camera.aspect = aspect;
      camera.updateProjectionMatrix();
    }
  }
  window.addEventListener('resize', resize);
  resize();

  function render() {
    const height = view.clientHeight;
    renderer.setScissor(0, 0, view.clientWidth, height);
    renderer.setViewport(0, 0, view.clientWidth, height);
    renderer.setClearColor(panes.length > 1 ? 0xeaedf4 : sky);
    renderer.clear();
    for (const pane of panes) {
      const { x, y, width: w, height: h } = pane.rect;
      renderer.setViewport(x, height - y - h, w, h);
      renderer.setScissor(x, height - y - h, w, h);
      setAspect(pane);
      renderer.render(pane.scene, camera);
    }
  }
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
      render();
    }
  });
  setFrame(0);

  // The test hook: the drawn poses (each object's world matrix) at the frames of the asked moments,
  // and where each centre falls in its pane (pixels from the pane's top left); `&size=854x480`
  // hides the controls and makes each pane that size, as the video's frame is (panes edge to edge).
  // A comparison's panes each start with a line "PANE n" (from 1).
  const probe = /#probe=([0-9.,]+)/.exec(window.location.hash);
  if (probe) {
    const size = /&size=(\d+)x(\d+)/.exec(window.location.hash);
    if (size) {
      document.body.classList.add('bare');
      exactPanes = [Number(size[1]), Number(size[2])];
      const columns = panes.length > 1 ? 2 : 1, rows = Math.ceil(panes.length / columns);
      view.style.width = columns * exactPanes[0] + 'px';
      view.style.height = rows * exactPanes[1] + 'px';
      resize();
    }
    const lines = ['VIEW ' + panes[0].rect.width + ' ' + panes[0].rect.height];
    for (const text of probe[1].split(',')) {
      const k = Math.round(Number(text) * run.fps);
      setFrame(k);
      const time = (k / run.fps).toFixed(6);
      const hex = (material) => '#' + material.color.getHexString(THREE.SRGBColorSpace);
      for (const pane of panes) {
        if (panes.length > 1) lines.push('PANE ' + (pane.index + 1));
        pane.scene.updateMatrixWorld(true);
        setAspect(pane);
        camera.updateMatrixWorld(true);  // not in the scene: render() would, but nothing has rendered yet
        pane.objects.forEach((object, i) => {
          if (pane.run.bodies[i].shape === 'plane') return;
          const position = new THREE.Vector3(), rotation = new THREE.Quaternion(), scale = new THREE.Vector3();
          object.matrixWorld.decompose(position, rotation, scale);
          lines.push(['POSE', time, position.x, position.y, position.z, rotation.w, rotation.x, rotation.y, rotation.z, pane.run.bodies[i].name].join(' '));
          const seen = position.clone().project(camera);
          lines.push(['PIXEL', time, (seen.x + 1) / 2 * pane.rect.width, (1 - seen.y) / 2 * pane.rect.height, pane.run.bodies[i].name].join(' '));
        });
        // The marks as drawn: each arrow's origin and vector (shaft and head together), each line's
        // ends, each dot's place, with their colours (sRGB).
        pane.pools.shafts.forEach((shaft, i) => {
          if (!shaft.visible) return;
          const head = pane.pools.heads[i];
          const along = up.clone().applyQuaternion(shaft.quaternion).multiplyScalar(shaft.scale.y + head.scale.y);
          lines.push(['ARROW', time, shaft.position.x, shaft.position.y, shaft.position.z, along.x, along.y, along.z, hex(shaft.material)].join(' '));
        });
        pane.pools.rods.forEach((rod) => {
          if (!rod.visible) return;
          const to = up.clone().applyQuaternion(rod.quaternion).multiplyScalar(rod.scale.y).add(rod.position);
          lines.push(['LINE', time, rod.position.x, rod.position.y, rod.position.z, to.x, to.y, to.z, hex(rod.material)].join(' '));
        });
        pane.pools.dots.forEach((dot) => {
          if (dot.visible) lines.push(['DOT', time, dot.position.x, dot.position.y, dot.position.z, hex(dot.material)].join(' '));
        });
      }
      // The equations shown: "EQUATION t place pane hash opacity" (pane 0: the view's; hash: FNV-1a
      // of the SVG's text).
      const fnv = (text) => {
        let hash = 0x811c9dc5;
        for (let i = 0; i < text.length; ++i) hash = Math.imul(hash ^ text.charCodeAt(i), 0x01000193) >>> 0;
        return hash;
      };
      // Each plot's curves as drawn: "PLOT t plot curve t_last value_last" (from 0; the last point shown).
      plots.forEach(({ curves }, k) => curves.forEach((curve, c) => {
        if (curve.shown > 0) lines.push(['PLOT', time, k, c, curve.times[curve.shown - 1], curve.values[curve.shown - 1]].join(' '));
      }));
      for (const element of panelElements.values()) {
        if (!element.isConnected) continue;
        const box = element.closest('.pane');
        const where = element.parentElement.className.replace('corner ', '');
        const paneNumber = box ? panes.findIndex((p) => p.box === box) + 1 : 0;
        lines.push(['EQUATION', time, where, paneNumber, fnv(run.svgs[run.panels[Number(element.dataset.panel)].svg]), element.style.opacity].join(' '));
      }
    }
    render();
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
      follow.checked = kept.following;
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
                                                           time: frame / run.fps, playing, following: follow.checked }));
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
  // Where a body's centre falls in the page (CSS pixels from its top left), for a test's click; in
  // pane `p` (from 0) of a comparison.
  function pixelOf(name, p = 0) {
    const pane = panes[p];
    const object = pane.objects[pane.run.bodies.findIndex((body) => body.name === name)];
    setAspect(pane);
    camera.updateMatrixWorld(true);
    const seen = object.position.clone().project(camera);
    const box = renderer.domElement.getBoundingClientRect();
    return [box.left + pane.rect.x + ((seen.x + 1) / 2) * pane.rect.width, box.top + pane.rect.y + ((1 - seen.y) / 2) * pane.rect.height];
  }
  // `advance` for a test: from frame k, how far `seconds` of playing take the simulated time.
  const playedFrom = (k, seconds) => { shownTime = k / run.fps; return advance(seconds); };
  // A body's pose at frame k (x y z, w x y z) in pane `p` (from 0), for a test.
  const poseOf = (name, k, p = 0) => {
    const at = (k * panes[p].bodyCount + panes[p].run.bodies.findIndex((body) => body.name === name)) * 7;
    return Array.from(panes[p].poses.subarray(at, at + 7));
  };
  window.impulsePage = { run, panes: paneRuns, frameCount, setFrame, errors, camera, controls, version,
                         frame: () => frame, pixelOf, poseOf, playedFrom };
}

unpackedRun().then(start).catch((failure) => report('error: ' + failure));
