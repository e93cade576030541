// A click on a body in `impulse export`'s page (headless Chromium, driven by Playwright) shows its
// numbers at that moment: each equals what the law gives from the trace of the same run (velocity
// and spin as traced, momentum m v, kinetic energy ½ m v² + ½ ω·Iω with I from the shape's formula,
// potential energy m g y). A drag orbits and chooses nothing; a click on the sky closes the panel.
//   node body_panel_test.mjs IMPULSE_PROGRAM SCRATCH_DIR NODE_MODULES
import { execFileSync } from 'node:child_process';
import fs from 'node:fs';
import path from 'node:path';
import { pathToFileURL } from 'node:url';
import { check, finish, launchChromium } from '../support/browser.mjs';

const [program, scratch, nodeModules] = process.argv.slice(2);

// A ball and a brick thrown upwards, spinning; their inertia from the shapes' formulas.
fs.rmSync(scratch, { recursive: true, force: true });
fs.mkdirSync(scratch, { recursive: true });
const scene = path.join(scratch, 'thrown.toml');
fs.writeFileSync(scene, `[scene]
title = "Thrown"
duration = 1.2

[camera]
position = [0.5, 1.6, 6]
target = [0.5, 1.4, 0]

[[body]]
name = "ground"
shape = "plane"

[[body]]
name = "ball"
shape = "sphere"
radius = 0.2
mass = 2
position = [-0.4, 1.2, 0]
velocity = [0.6, 2.5, 0]
angular_velocity = [0, 0, -5]

[[body]]
name = "brick"
shape = "box"
size = [0.4, 0.2, 0.6]
mass = 3
position = [1.4, 1.2, 0]
velocity = [-0.4, 2.5, 0]
angular_velocity = [1, 2, 0.5]
`);
const mass = { ball: 2, brick: 3 };
const inertia = { ball: Array(3).fill(0.4 * 2 * 0.2 ** 2),                                // 2/5 m r²
                  brick: [[0.2, 0.6], [0.4, 0.6], [0.4, 0.2]].map(([b, c]) => (3 / 12) * (b * b + c * c)) };  // m (b² + c²)/12
const page = path.join(scratch, 'thrown.html'), trace = path.join(scratch, 'trace.csv');
execFileSync(program, ['-q', 'export', scene, '-o', page]);
execFileSync(program, ['-q', 'simulate', scene, '--trace', trace]);

// The trace's rows at a moment, by body: x y z, qw qx qy qz, v, ω.
function traced(moment) {
  const rows = {};
  for (const line of fs.readFileSync(trace, 'utf8').trim().split('\n').slice(1)) {
    const cells = line.split(',');
    if (Math.abs(Number(cells[0]) - moment) > 1e-9) continue;
    const n = cells.slice(3).map(Number);
    rows[cells[2].replaceAll('"', '')] = { x: n.slice(0, 3), q: n.slice(3, 7), v: n.slice(7, 10), w: n.slice(10, 13) };
  }
  return rows;
}
// ω in the body's frame: the conjugate of q turning ω.
function intoBody([w, x, y, z], v) {
  const cross = (a, b) => [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
  const u = [-x, -y, -z];
  const t = cross(u, v).map((c) => 2 * c);
  const s = cross(u, t);
  return v.map((c, k) => c + w * t[k] + s[k]);
}

const browser = await launchChromium(nodeModules);
const view = await browser.newPage({ viewport: { width: 1000, height: 700 } });
const complaints = [];
view.on('pageerror', (error) => complaints.push(error.message));
await view.goto(pathToFileURL(page).href);
await view.waitForFunction(() => window.impulsePage !== undefined);  // the viewer and the run are unpacked first
const shown = () => view.evaluate(() => {
  const panel = document.getElementById('panel');
  return panel.hidden ? null : { ...panel.dataset, text: panel.textContent };
});
const near = (a, b, tolerance) => a.length === b.length && a.every((v, k) => Math.abs(v - b[k]) <= tolerance);

for (const moment of [0.4, 0.9]) {
  const rows = traced(moment);
  for (const name of ['ball', 'brick']) {
    await view.evaluate((t) => window.impulsePage.setFrame(Math.round(t * window.impulsePage.run.fps)), moment);
    const [x, y] = await view.evaluate((n) => window.impulsePage.pixelOf(n), name);
    await view.mouse.click(x, y);
    const panel = await shown();
    const where = name + ' at ' + moment + ' s';
    if (!panel) { check(false, where + ': a click at ' + x + ', ' + y + ' shows the panel'); continue; }
    const numbers = (text) => text.split(' ').map(Number);
    const row = rows[name];
    const m = mass[name];
    const wb = intoBody(row.q, row.w);
    const kinetic = 0.5 * m * row.v.reduce((a, c) => a + c * c, 0) + 0.5 * wb.reduce((a, c, k) => a + inertia[name][k] * c * c, 0);
    check(panel.body === name && Math.abs(Number(panel.time) - moment) < 1e-9, where + ': the panel names it and the moment');
    check(panel.text.includes(name) && panel.text.includes('kinetic') && panel.text.includes('potential'), where + ': and says so in words');
    check(near(numbers(panel.velocity), row.v, 5e-5), where + ': velocity ' + panel.velocity + ' as traced ' + row.v.join(' '));
    check(near(numbers(panel.spin), row.w, 5e-5), where + ': spin ' + panel.spin + ' as traced ' + row.w.join(' '));
    check(near(numbers(panel.momentum), row.v.map((c) => m * c), m * 5e-5), where + ': momentum m v');
    check(Math.abs(Number(panel.kinetic) - kinetic) < 1e-3 * Math.max(1, kinetic), where + ': kinetic energy ' + panel.kinetic + ', by the law ' + kinetic);
    check(Math.abs(Number(panel.potential) - m * 9.81 * row.x[1]) < m * 9.81 * 2e-5, where + ': potential energy ' + panel.potential + ', m g y = ' + m * 9.81 * row.x[1]);
  }
}

// A drag orbits the camera and chooses nothing new; a click on the sky closes the panel.
const before = await view.evaluate(() => window.impulsePage.camera.position.toArray());
await view.mouse.move(150, 150);
await view.mouse.down();
await view.mouse.move(250, 180, { steps: 8 });
await view.mouse.up();
const after = await view.evaluate(() => window.impulsePage.camera.position.toArray());
check(!near(before, after, 1e-3), 'a drag orbits the camera');
check((await shown())?.body === 'brick', 'a drag leaves the panel as it was');
await view.mouse.click(150, 90);
check((await shown()) === null, 'a click on the sky closes the panel');
check(complaints.length === 0, 'no error in the page: ' + complaints.join('; '));
await browser.close();
finish();
