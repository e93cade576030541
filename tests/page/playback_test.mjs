// The page plays as the video does: at the scene's speed, slowed to slow_motion_speed within
// slow_motion_window of each impact stronger than slow_motion_impulse (the impacts read from
// `impulse simulate --contacts`, the settings from the scene file), its clock saying so; in
// headless Chromium, the playing advanced by a given real time (no clock read).
//   node playback_test.mjs IMPULSE_PROGRAM SOURCE_DIR SCRATCH_DIR NODE_MODULES
import { execFileSync } from 'node:child_process';
import fs from 'node:fs';
import path from 'node:path';
import { pathToFileURL } from 'node:url';
import { check, finish, launchChromium } from '../support/browser.mjs';

const [program, source, scratch, nodeModules] = process.argv.slice(2);
fs.rmSync(scratch, { recursive: true, force: true });
fs.mkdirSync(scratch, { recursive: true });
const scene = path.join(source, 'assets', 'scenes', 'bounce.toml');
const setting = (name) => Number(new RegExp('^' + name + '\\s*=\\s*([0-9.]+)', 'm').exec(fs.readFileSync(scene, 'utf8'))[1]);
const [threshold, slow, window] = ['slow_motion_impulse', 'slow_motion_speed', 'slow_motion_window'].map(setting);
const page = path.join(scratch, 'bounce.html'), contacts = path.join(scratch, 'contacts.csv');
execFileSync(program, ['-q', 'export', scene, '-o', page]);
execFileSync(program, ['-q', 'simulate', scene, '--contacts', contacts]);
const impacts = [];
for (const line of fs.readFileSync(contacts, 'utf8').trim().split('\n').slice(1)) {
  const cells = line.split(',');
  if (Number(cells[11]) >= threshold) impacts.push(Number(cells[0]));
}
check(impacts.length > 0, 'the scene has impacts: ' + impacts.map((t) => t.toFixed(3)).join(' '));

const browser = await launchChromium(nodeModules);
const view = await browser.newPage({ viewport: { width: 1000, height: 700 } });
await view.goto(pathToFileURL(page).href);
await view.waitForFunction(() => window.impulsePage !== undefined);  // the viewer and the run are unpacked first
const fps = await view.evaluate(() => window.impulsePage.run.fps);
const nearest = (t) => Math.min(...impacts.map((impact) => Math.abs(t - impact)));
let inside = 0, outside = 0;
for (let k = 0; k + 1 < 6 * fps; ++k) {
  const t = k / fps;
  // 0.02 s of playing: within a window the whole way, or clear of every window and its 0.1 s ease.
  if (nearest(t) < window - 0.02 * slow - 1e-6 && nearest(t + 0.02 * slow) < window) {
    const played = await view.evaluate((k) => window.impulsePage.playedFrom(k, 0.02), k);
    if (Math.abs(played - (t + 0.02 * slow)) >= 1e-9) check(false, `at ${t.toFixed(3)} s, inside an impact's window: 0.02 s plays ${(played - t).toFixed(5)} s`);
    ++inside;
  } else if (nearest(t) > window + 0.1 + 0.03 && nearest(t + 0.02) > window + 0.1) {
    const played = await view.evaluate((k) => window.impulsePage.playedFrom(k, 0.02), k);
    if (Math.abs(played - (t + 0.02)) >= 1e-9) check(false, `at ${t.toFixed(3)} s, clear of impacts: 0.02 s plays ${(played - t).toFixed(5)} s`);
    ++outside;
  }
}
check(inside >= 3 && outside >= 3, `0.02 s of playing from ${inside} moments inside windows plays ${0.02 * slow} s, from ${outside} clear of them 0.02 s`);
// The clock says so at an impact, and not away from one.
await view.evaluate((k) => window.impulsePage.setFrame(k), Math.round(impacts[0] * fps));
const during = await view.locator('#clock').textContent();
await view.evaluate(() => window.impulsePage.setFrame(1));
const before = await view.locator('#clock').textContent();
check(during.includes('slow motion \u00d7' + slow.toFixed(2)) && !before.includes('slow'), `the clock: "${during}", then "${before}"`);
await browser.close();
finish();
