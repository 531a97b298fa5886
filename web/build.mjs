// Bundles web/src into one self-contained HTML file: the minified script inlined into
// index.html, no request to anything at run time.
//   node build.mjs OUT.html [--node-modules DIR] [--dev]
// --node-modules: where `npm ci` put the packages (the CMake build keeps them in the build
// tree); by default web/node_modules. --dev: unminified, with an inline source map.
import { createRequire } from 'node:module';
import { mkdirSync, readFileSync, writeFileSync } from 'node:fs';
import { dirname, join, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';

const here = dirname(fileURLToPath(import.meta.url));
const args = process.argv.slice(2);
let out = null;
let nodeModules = join(here, 'node_modules');
let dev = false;
for (let i = 0; i < args.length; i++) {
  if (args[i] === '--node-modules') nodeModules = resolve(args[++i]);
  else if (args[i] === '--dev') dev = true;
  else if (!out) out = resolve(args[i]);
  else fail(`unexpected argument ${args[i]}`);
}
if (!out) fail('usage: node build.mjs OUT.html [--node-modules DIR] [--dev]');

function fail(message) {
  console.error(`build.mjs: ${message}`);
  process.exit(1);
}

// esbuild is resolved from the given node_modules, not from this file's folder, so that the
// source tree needs no node_modules of its own.
const esbuild = createRequire(join(nodeModules, 'resolve.js'))('esbuild');

const result = await esbuild.build({
  entryPoints: [join(here, 'src', 'main.js')],
  bundle: true,
  format: 'iife',
  target: 'es2020',
  minify: !dev,
  sourcemap: dev ? 'inline' : false,
  charset: 'ascii',          // the C++ side embeds the page as plain ASCII text
  legalComments: 'eof',      // three.js's licence notice stays in the page
  nodePaths: [nodeModules],
  write: false,
  logLevel: 'warning',
});
let script = result.outputFiles[0].text;
// The script sits inside <script>: a "</script" or "<!--" in a string would end or confuse it.
script = script.replace(/<\/(script)/gi, '<\\/$1').replace(/<!--/g, '<\\!--');

const marker = '<!--SPHERESET_DATA-->';
const template = readFileSync(join(here, 'index.html'), 'utf8');
if (template.split(marker).length !== 2) fail(`index.html must hold ${marker} exactly once`);
if (!template.includes('<!--SPHERESET_SCRIPT-->')) fail('index.html lacks <!--SPHERESET_SCRIPT-->');
// A function as replacement: the script's "$&" and "$1" must stay as they are.
const html = template.replace('<!--SPHERESET_SCRIPT-->', () => `<script>${script}</script>`);
if (html.split(marker).length !== 2) fail(`the bundle contains ${marker}`);

mkdirSync(dirname(out), { recursive: true });
writeFileSync(out, html);
console.log(`build.mjs: ${out} (${(html.length / 1024).toFixed(0)} KiB)`);
