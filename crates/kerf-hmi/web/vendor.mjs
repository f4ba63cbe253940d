// Copies the three.js files the screen uses from the npm package (the
// version locked in package-lock.json) into vendor/, which the kerf
// binary embeds. `node vendor.mjs --check` fails when vendor/ differs from
// the installed package (run after `npm ci`).
import { readFileSync, writeFileSync, mkdirSync } from 'node:fs';
import { dirname, join } from 'node:path';
import { fileURLToPath } from 'node:url';

const here = dirname(fileURLToPath(import.meta.url));
const files = [
  ['node_modules/three/build/three.module.js', 'vendor/three.module.js'],
  ['node_modules/three/build/three.core.js', 'vendor/three.core.js'],
  ['node_modules/three/examples/jsm/controls/OrbitControls.js', 'vendor/OrbitControls.js'],
  ['node_modules/three/LICENSE', 'vendor/three.LICENSE'],
];
const check = process.argv.includes('--check');
let bad = 0;
mkdirSync(join(here, 'vendor'), { recursive: true });
for (const [from, to] of files) {
  const src = readFileSync(join(here, from));
  if (check) {
    let have = null;
    try { have = readFileSync(join(here, to)); } catch { /* missing */ }
    if (!have || !have.equals(src)) {
      console.error(`${to} differs from ${from}: run npm run vendor`);
      bad++;
    }
  } else {
    writeFileSync(join(here, to), src);
  }
}
const version = JSON.parse(readFileSync(join(here, 'node_modules/three/package.json'))).version;
console.log(`three ${version}: ${files.length} files ${check ? (bad ? 'differ' : 'match') : 'copied'}`);
process.exit(bad ? 1 : 0);
