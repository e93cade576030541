// The Khronos glTF validator (npm gltf-validator, web/node_modules) on one .glb:
//   node tests/page/validate_glb.mjs FILE.glb
// prints "errors N warnings N infos N hints N", then each message as "SEVERITY CODE POINTER: TEXT"
// (severity 0 error, 1 warning, 2 info, 3 hint). Exits 0 when the validator ran, whatever it found;
// 2 when it could not.
import { readFileSync } from 'node:fs';
import { createRequire } from 'node:module';

const require = createRequire(new URL('../../web/node_modules/', import.meta.url));
const validator = require('gltf-validator');

const file = process.argv[2];
if (!file) {
  console.error('usage: node tests/page/validate_glb.mjs FILE.glb');
  process.exit(2);
}
try {
  const report = await validator.validateBytes(new Uint8Array(readFileSync(file)), { maxIssues: 0, format: 'glb' });
  const issues = report.issues;
  console.log(`errors ${issues.numErrors} warnings ${issues.numWarnings} infos ${issues.numInfos} hints ${issues.numHints}`);
  for (const message of issues.messages) console.log(`${message.severity} ${message.code} ${message.pointer ?? ''}: ${message.message}`);
} catch (error) {
  console.error(`validate_glb: ${file}: ${error}`);
  process.exit(2);
}
