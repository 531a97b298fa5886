// What the browser tests share: their arguments, the headless Chromium, the `sphereset view`
// server they start, console errors they collect, and the pixels of a screenshot.
//   node TEST.mjs --node-modules DIR --work DIR [--chromium CHROMIUM] [--cli SPHERESET] [--page PAGE]
// (--cli for the tests of the command, --page for the page alone)
import { spawn, execFileSync } from 'node:child_process';
import { mkdirSync } from 'node:fs';
import { createRequire } from 'node:module';
import { join } from 'node:path';

export function parseArgs() {
  const args = { cli: null, chromium: '/usr/bin/chromium', nodeModules: null, work: null, page: null };
  const argv = process.argv.slice(2);
  for (let i = 0; i < argv.length; i += 2) {
    const key = {
      '--cli': 'cli', '--chromium': 'chromium', '--node-modules': 'nodeModules', '--work': 'work',
      '--page': 'page',
    }[argv[i]];
    if (!key || argv[i + 1] === undefined) fail(`bad argument ${argv[i]}`);
    args[key] = argv[i + 1];
  }
  for (const key of ['nodeModules', 'work']) if (!args[key]) fail(`--${key} is required`);
  mkdirSync(args.work, { recursive: true });
  return args;
}

export function fail(message) {
  console.error(`FAIL: ${message}`);
  process.exit(1);
}

// A failed check is reported and the test goes on, so one run shows every check that fails;
// the test fails at the end.
const failures = [];
export function check(condition, message) {
  if (!condition) {
    failures.push(message);
    console.log(`not ok: ${message}`);
  } else {
    console.log(`ok: ${message}`);
  }
}

export function near(a, b, relative) {
  return Math.abs(a - b) <= relative * Math.max(1, Math.abs(a), Math.abs(b));
}

// puppeteer-core from the build tree's packages (web/package-lock.json); it never downloads
// a browser, the system's Chromium is used.
export async function launchBrowser(args) {
  const puppeteer = createRequire(join(args.nodeModules, 'resolve.js'))('puppeteer-core');
  return puppeteer.launch({
    executablePath: args.chromium,
    args: ['--headless=new', '--use-angle=swiftshader', '--enable-unsafe-swiftshader', '--no-sandbox',
      '--disable-gpu-sandbox'],
    protocolTimeout: 120000,
  });
}

// A page that records every console error and uncaught exception.
export async function openPage(browser, url) {
  const page = await browser.newPage();
  await page.setViewport({ width: 900, height: 600 });
  const errors = [];
  page.on('console', (m) => { if (m.type() === 'error') errors.push(`console: ${m.text()}`); });
  page.on('pageerror', (e) => errors.push(`page error: ${e.message}`));
  page.on('requestfailed', (r) => errors.push(`request failed: ${r.url()} ${r.failure()?.errorText}`));
  await page.goto(url, { waitUntil: 'load' });
  await page.evaluate(() => window.sphereset.ready);
  return { page, errors };
}

// Starts `sphereset view ARGS --no-open --port 0` and resolves with its URL once it has printed
// it; the server is stopped when this process exits.
export function startView(args, viewArgs) {
  if (!args.cli) throw new Error('--cli SPHERESET is required');
  const child = spawn(args.cli, ['view', ...viewArgs, '--no-open', '--port', '0'],
    { stdio: ['ignore', 'pipe', 'pipe'] });
  process.on('exit', () => child.kill());
  let output = '';
  return new Promise((resolve, reject) => {
    const timer = setTimeout(() => reject(new Error(`no URL from sphereset view: ${output}`)), 60000);
    const look = (chunk) => {
      output += chunk;
      const match = output.match(/sphereset view: (http:\/\/127\.0\.0\.1:\d+\/\?token=\S+)/);
      if (match) {
        clearTimeout(timer);
        resolve({ url: match[1], child });
      }
    };
    child.stdout.on('data', look);
    child.stderr.on('data', (chunk) => { output += chunk; });
    child.on('exit', (code) => {
      clearTimeout(timer);
      reject(new Error(`sphereset view exited (${code}): ${output}`));
    });
  });
}

export function runCli(args, cliArgs) {
  if (!args.cli) throw new Error('--cli SPHERESET is required');
  return execFileSync(args.cli, cliArgs, { encoding: 'utf8' });
}

export async function pageStatus(page) {
  return page.$eval('#status', (e) => e.textContent.trim());
}

// The message line, which must not hold an error after a normal step.
export async function pageMessage(page) {
  return page.$eval('#message', (e) => ({ text: e.textContent, error: e.classList.contains('error') }));
}

// Runs body(pngBase64, ...) in a blank page where window.decodePng(base64) gives a PNG's
// { width, height, data (RGBA) }, decoded by the browser itself.
async function withDecoder(browser, body, ...args) {
  const page = await browser.newPage();
  try {
    await page.evaluate(() => {
      window.decodePng = async (base64) => {
        const image = new Image();
        image.src = `data:image/png;base64,${base64}`;
        await image.decode();
        const canvas = document.createElement('canvas');
        canvas.width = image.width;
        canvas.height = image.height;
        const context = canvas.getContext('2d');
        context.drawImage(image, 0, 0);
        return { width: image.width, height: image.height,
          data: context.getImageData(0, 0, image.width, image.height).data };
      };
    });
    return await page.evaluate(body, ...args);
  } finally {
    await page.close();
  }
}

// Distinct colours of a PNG and, given a second one of the same size, the pixels that differ.
export function pixelStats(browser, png, other = null) {
  return withDecoder(browser, async (a, b) => {
    const pixels = (await window.decodePng(a)).data;
    const colours = new Set();
    for (let i = 0; i < pixels.length; i += 4) {
      colours.add((pixels[i] << 16) | (pixels[i + 1] << 8) | pixels[i + 2]);
    }
    let differing = null;
    if (b) {
      const second = (await window.decodePng(b)).data;
      differing = 0;
      for (let i = 0; i < pixels.length; i += 4) {
        if (pixels[i] !== second[i] || pixels[i + 1] !== second[i + 1] || pixels[i + 2] !== second[i + 2]) {
          differing++;
        }
      }
    }
    return { colours: colours.size, differing };
  }, png.toString('base64'), other ? other.toString('base64') : null);
}

// The pixels of a PNG whose [r, g, b] satisfy `predicateSource` (an expression of r, g and b),
// and its size.
export function countPixels(browser, png, predicateSource) {
  return withDecoder(browser, async (base64, source) => {
    const { width, height, data } = await window.decodePng(base64);
    const predicate = new Function('r', 'g', 'b', `return ${source};`);
    let count = 0;
    for (let i = 0; i < data.length; i += 4) if (predicate(data[i], data[i + 1], data[i + 2])) count++;
    return { count, width, height };
  }, png.toString('base64'), predicateSource);
}

// The view's canvas only: the panel beside it holds text that changes on its own.
export async function canvasShot(page) {
  const canvas = await page.$('#viewport canvas');
  return canvas.screenshot({ type: 'png' });
}

// Runs a test body with a browser, failing the process on any exception.
export async function runTest(body) {
  const args = parseArgs();
  const browser = await launchBrowser(args);
  try {
    await body(args, browser);
    if (failures.length) {
      console.error(`FAIL: ${failures.length} checks failed:\n  ${failures.join('\n  ')}`);
      process.exitCode = 1;
    } else {
      console.log('PASS');
    }
  } catch (e) {
    console.error(`FAIL: ${e.stack || e.message}`);
    process.exitCode = 1;
  } finally {
    await browser.close();
  }
  process.exit(process.exitCode || 0);
}

export function checkNoErrors(errors, what) {
  check(errors.length === 0, `no console errors ${what}${errors.length ? `: ${errors.join(' | ')}` : ''}`);
}
