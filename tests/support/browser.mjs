// What the browser tests share: Debian's Chromium started by Playwright (playwright-core from
// web/node_modules, which downloads no browser of its own; IMPULSE_CHROMIUM names another), with
// SwiftShader's WebGL; and a tally of checks that sets the exit code.
import path from 'node:path';
import { pathToFileURL } from 'node:url';

export async function launchChromium(nodeModules) {
  const { chromium } = await import(pathToFileURL(path.resolve(nodeModules, 'playwright-core', 'index.mjs')).href);
  return chromium.launch({ executablePath: process.env.IMPULSE_CHROMIUM || '/usr/lib/chromium/chromium',
                           args: ['--no-sandbox', '--enable-unsafe-swiftshader'] });
}

let failures = 0;
export function check(condition, what) {
  console.log((condition ? 'ok     ' : 'FAILED ') + what);
  if (!condition) failures += 1;
}
export function finish() {
  console.log(failures === 0 ? 'all passed' : failures + ' failed');
  process.exit(failures === 0 ? 0 : 1);
}
