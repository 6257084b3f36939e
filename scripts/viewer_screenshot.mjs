// node scripts/viewer_screenshot.mjs PAGE.html OUT.png FRACTION: the page at
// s = FRACTION × length, 1280×720, as PNG (scripts/viewer_screenshot.sh).
import { createRequire } from 'node:module';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { fileURLToPath, pathToFileURL } from 'node:url';

const [page, out, fraction = '0.5'] = process.argv.slice(2);
const root = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..');
const { chromium } = createRequire(path.join(root, 'web', 'package.json'))('playwright-core');
const profile = fs.mkdtempSync(path.join(os.tmpdir(), 'rollspin-chromium-'));
const context = await chromium.launchPersistentContext(profile, {
  executablePath: '/usr/bin/chromium', headless: true, viewport: { width: 1280, height: 720 },
  args: ['--headless', '--no-sandbox', '--disable-gpu', '--disable-quic', '--no-first-run',
    '--disable-background-networking', '--disable-component-update', '--disable-sync'],
});
await context.route('**/*', (r) => (/^(file|data|blob):/.test(r.request().url()) ? r.continue() : r.abort()));
const tab = await context.newPage();
await tab.goto(pathToFileURL(path.resolve(page)).href);
await tab.evaluate(() => window.rollspin.ready);
await tab.evaluate((f) => window.rollspin.seek(f * window.rollspin.length), Number(fraction));
await tab.waitForTimeout(200);
await tab.screenshot({ path: out });
await context.close();
fs.rmSync(profile, { recursive: true, force: true });
console.log(`wrote ${out}`);
