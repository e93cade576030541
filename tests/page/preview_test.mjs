// `impulse preview`: the real program serving a scene, asked by raw HTTP requests and by headless
// Chromium (driven by Playwright). It answers / and /state on 127.0.0.1 alone and nothing else;
// the page picks up a saved change with its camera and moment kept, shows a scene's error with its
// file, line and field over the last good run, and comes back when the file is mended; Ctrl-C
// stops the program.
//   node preview_test.mjs IMPULSE_PROGRAM SCRATCH_DIR NODE_MODULES
import { spawn } from 'node:child_process';
import { once } from 'node:events';
import fs from 'node:fs';
import net from 'node:net';
import os from 'node:os';
import path from 'node:path';
import zlib from 'node:zlib';
import { check, finish, launchChromium } from '../support/browser.mjs';

const [program, scratch, nodeModules] = process.argv.slice(2);
const sleep = (ms) => new Promise((done) => setTimeout(done, ms));
async function until(what, test, seconds = 30) {
  const end = Date.now() + 1000 * seconds;
  for (;;) {
    const value = await test();
    if (value) return value;
    if (Date.now() > end) throw new Error('waited ' + seconds + ' s for ' + what);
    await sleep(50);
  }
}

// A scene of a ground and one box at x = `x`; `broken` puts a wrong value on line 12.
fs.rmSync(scratch, { recursive: true, force: true });
fs.mkdirSync(scratch, { recursive: true });
const scene = path.join(scratch, 'scene.toml');
const sceneText = (x, broken = false) => `[scene]
title = "Preview"
duration = 1.0

[[body]]
name = "ground"
shape = "plane"

[[body]]
name = "box"
shape = "box"
restitution = ${broken ? '"bouncy"' : '0.2'}
size = [0.4, 0.4, 0.4]
position = [${x}, 0.2, 0]
`;
// Written in place as an editor saves: a new file renamed over the old one.
function save(text) {
  fs.writeFileSync(scene + '.new', text);
  fs.renameSync(scene + '.new', scene);
}
save(sceneText(0));

// The program, and its address from its first line.
const server = spawn(program, ['preview', scene, '--port', '0'], { stdio: ['ignore', 'pipe', 'pipe'] });
let said = '';
server.stdout.on('data', (chunk) => { said += chunk; });
server.stderr.on('data', (chunk) => { process.stderr.write('impulse: ' + chunk); });
const address = await until('the address', () => /http:\/\/127\.0\.0\.1:(\d+)\//.exec(said));
const port = Number(address[1]);
console.log('serving on ' + address[0]);

// One raw request (the path as written, `..` and all); its status and body.
async function ask(target, host = '127.0.0.1:' + port, method = 'GET') {
  const socket = net.connect(port, '127.0.0.1');
  await once(socket, 'connect');
  socket.write(`${method} ${target} HTTP/1.1\r\nHost: ${host}\r\nContent-Length: 0\r\nConnection: close\r\n\r\n`);
  const chunks = [];
  for await (const chunk of socket) chunks.push(chunk);
  const text = Buffer.concat(chunks).toString('utf8');
  return { status: Number(text.split(' ')[1]), body: text.slice(text.indexOf('\r\n\r\n') + 4) };
}

// Whether a connection to the port at `host` opens.
async function opens(host) {
  const socket = net.connect(port, host);
  const open = await once(socket, 'connect').then(() => true, () => false);
  socket.destroy();
  return open;
}

const home = await ask('/');
// The run in a page: JSON, gzipped, in base64.
const runOf = (html) => {
  const packed = /<script id="impulse-run" type="application\/gzip;base64">([^<]*)<\/script>/.exec(html);
  return packed ? JSON.parse(zlib.gunzipSync(Buffer.from(packed[1], 'base64')).toString()) : null;
};
const homeRun = home.status === 200 ? runOf(home.body) : null;
check(home.body.includes('id="impulse-live"') && homeRun !== null && homeRun.bodies.some((body) => body.name === 'box'),
      'GET / is the live page with the scene');
const state = await ask('/state');
check(state.status === 200 && JSON.parse(state.body).error === '', 'GET /state: ' + state.body);
for (const target of ['/scene.toml', '/../scene.toml', '/%2e%2e/scene.toml', '/state/../scene.toml', '/..%2fscene.toml',
                      '//etc/passwd', '/index.html', '/state/x', '/' + scene]) {
  const answer = await ask(target);
  check(answer.status === 404 && !answer.body.includes('restitution'), 'GET ' + target + ' is 404 (' + answer.status + ')');
}
for (const host of ['evil.example:' + port, 'evil.example', '127.0.0.1', 'localhost.evil.example:' + port]) {
  const answer = await ask('/', host);
  check(answer.status === 403 && !answer.body.includes('restitution'), 'a request for ' + host + ' is 403 (' + answer.status + ')');
}
const posted = await ask('/', '127.0.0.1:' + port, 'POST');
check(posted.status >= 400 && !posted.body.includes('restitution'), 'POST is refused (' + posted.status + ')');
// Loopback only: on every other address of this machine the port is closed.
for (const entries of Object.values(os.networkInterfaces()))
  for (const entry of entries) {
    if (entry.internal || entry.family !== 'IPv4') continue;
    check(!(await opens(entry.address)), 'the port is closed on ' + entry.address);
  }

// The page in Chromium.
const browser = await launchChromium(nodeModules);
const page = await browser.newPage({ viewport: { width: 1000, height: 700 } });
const complaints = [];
page.on('console', (message) => { if (message.type() === 'error') complaints.push(message.text()); });
page.on('pageerror', (error) => complaints.push(error.message));
page.on('requestfailed', (request) => complaints.push('failed: ' + request.url()));

const boxAt = () => page.evaluate(() => window.impulsePage.poseOf('box', 0)[0]);
const versionOf = () => page.evaluate(() => window.impulsePage.version);
await page.goto(address[0]);
await until('the page', () => page.evaluate(() => window.impulsePage !== undefined));
check(await boxAt() === 0, 'the page shows the box at x = 0');

// Orbit and scrub, then save a change: the page shows the new run from the same camera and moment.
await page.evaluate(() => {
  const p = window.impulsePage;
  p.camera.position.set(3, 2.5, 4);
  p.controls.target.set(0.5, 0.1, 0);
  p.controls.update();
  p.setFrame(12);
});
const before = await versionOf();
const saved = Date.now();
save(sceneText(1.5));
await until('the new run in the page', async () => {
  try { return (await versionOf()) !== before && (await boxAt()) === 1.5; } catch { return false; }  // navigating
});
console.log('the change showed ' + (Date.now() - saved) + ' ms after the save');
const kept = await page.evaluate(() => {
  const p = window.impulsePage;
  return { position: p.camera.position.toArray(), target: p.controls.target.toArray(), frame: p.frame() };
});
const near = (a, b) => a.every((v, k) => Math.abs(v - b[k]) < 1e-6);
check(near(kept.position, [3, 2.5, 4]) && near(kept.target, [0.5, 0.1, 0]), 'the camera is kept: ' + JSON.stringify(kept));
check(kept.frame === 12, 'the moment is kept: frame ' + kept.frame);

// A wrong value: the page says where, and keeps the last good run.
const good = await versionOf();
save(sceneText(-1, true));
const problem = await until('the error in the page', async () => {
  const text = await page.locator('#problem').textContent();
  return text ? text : null;
});
console.log('the page says: ' + problem.split('\n')[0]);
check(problem.includes('scene.toml:12') && problem.includes("'restitution'") && problem.includes("'box'"),
      'the error names the file, line 12, the body and the field');
check(await page.locator('#problem').isVisible(), 'the error is shown');
check(await versionOf() === good && await boxAt() === 1.5, 'the last good run stays');

// Mended: the new run, and no error.
save(sceneText(-1));
await until('the mended run', async () => {
  try { return (await boxAt()) === -1; } catch { return false; }
});
check(await page.locator('#problem').textContent() === '', 'the error is gone once the file is mended');
check(complaints.length === 0, 'no error in the browser: ' + complaints.join('; '));
await browser.close();

// Ctrl-C stops it, and the port closes.
server.kill('SIGINT');
const [code, signal] = await Promise.race([once(server, 'exit'), sleep(10000).then(() => [null, 'still running'])]);
check(signal === 'SIGINT' || code === 130, 'Ctrl-C stops the preview (' + code + ', ' + signal + ')');
check(!(await opens('127.0.0.1')), 'the port is closed after');
if (signal === 'still running') server.kill('SIGKILL');

finish();
