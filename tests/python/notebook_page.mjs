// The executed workshop notebook as nbconvert shows it in HTML, opened in headless Chromium
// (Playwright): the scene's page inline draws the scene with WebGL and reports no error.
//   node notebook_page.mjs NOTEBOOK.html NODE_MODULES
import path from 'node:path';
import { pathToFileURL } from 'node:url';
import { launchChromium } from '../support/browser.mjs';

const [notebook, nodeModules] = process.argv.slice(2);
const browser = await launchChromium(nodeModules);
const page = await browser.newPage({ viewport: { width: 1100, height: 900 } });
const complaints = [];
page.on('pageerror', (error) => complaints.push(error.message));
await page.goto(pathToFileURL(path.resolve(notebook)).href, { waitUntil: 'domcontentloaded' });
// In view: a frame of another origin out of view is not drawn.
const element = await page.waitForSelector('iframe[srcdoc]');
await element.scrollIntoViewIfNeeded();
const frame = await element.contentFrame();
await frame.waitForFunction(() => window.impulsePage !== undefined, null, { timeout: 30000 });
// The sliding box's colour among the frame's pixels, at a moment with the box in view.
const seen = await frame.evaluate(() => {
  const p = window.impulsePage;
  p.setFrame(Math.floor(p.frameCount / 3));
  return new Promise((done) => requestAnimationFrame(() => requestAnimationFrame(() => {
    const canvas = document.querySelector('#view canvas');
    const copy = document.createElement('canvas');
    copy.width = canvas.width;
    copy.height = canvas.height;
    const context = copy.getContext('2d');
    context.drawImage(canvas, 0, 0);
    const pixels = context.getImageData(0, 0, copy.width, copy.height).data;
    const body = p.panes[0].bodies.find((b) => b.name === 'sliding box');
    const want = body.colour.map((c) => 255 * c);
    let near = 0;
    for (let at = 0; at < pixels.length; at += 4)
      if (Math.abs(pixels[at] - want[0]) + Math.abs(pixels[at + 1] - want[1]) + Math.abs(pixels[at + 2] - want[2]) < 90) near += 1;
    done({ near, width: copy.width, height: copy.height, errors: p.errors.slice(), frames: p.frameCount,
           bodies: p.panes[0].bodies.map((b) => b.name) });
  })));
});
await browser.close();
console.log(JSON.stringify(seen));
const failures = [];
if (!seen.bodies.includes('sliding box')) failures.push('no sliding box in the page');
if (seen.frames < 2) failures.push('no frames');
if (seen.width < 300 || seen.height < 200) failures.push('the view is ' + seen.width + 'x' + seen.height);
if (seen.near < 100) failures.push('the sliding box is not drawn in its colour (' + seen.near + ' pixels)');
failures.push(...seen.errors, ...complaints);
console.log(failures.length ? 'FAILED: ' + failures.join('; ') : 'the notebook shows the page, the box drawn in ' + seen.near + ' pixels');
process.exit(failures.length ? 1 : 0);
