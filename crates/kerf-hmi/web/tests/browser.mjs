// Starting Debian's chromium through playwright-core (Playwright's own
// browser download is not used) and the kerf server for the tests.
import { chromium } from 'playwright-core';
import { spawn } from 'node:child_process';
import { mkdtempSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';

export const CHROMIUM = process.env.CHROMIUM || '/usr/bin/chromium';

/** A fresh headless chromium with its own profile folder. */
export async function launch() {
  const profile = mkdtempSync(join(tmpdir(), 'kerf-chromium-'));
  const ctx = await chromium.launchPersistentContext(profile, {
    executablePath: CHROMIUM,
    headless: true,
    viewport: { width: 1280, height: 800 },
    args: [
      '--headless', '--no-sandbox', '--disable-gpu', '--disable-background-networking',
      '--disable-component-update', '--disable-sync', '--no-first-run',
      '--enable-unsafe-swiftshader', '--use-angle=swiftshader',
    ],
  });
  ctx.cleanup = async () => {
    await ctx.close();
    rmSync(profile, { recursive: true, force: true });
  };
  return ctx;
}

/**
 * Starts `kerf serve` on 127.0.0.1 with a free port; resolves to
 * {url, proc, stop()} once it prints its address.
 */
export function serve(args, env = {}) {
  const bin = process.env.KERF || 'target/debug/kerf';
  const proc = spawn(bin, ['serve', '--bind', '127.0.0.1:0', ...args], {
    env: { ...process.env, ...env },
    stdio: ['ignore', 'pipe', 'pipe'],
  });
  let err = '';
  return new Promise((resolve, reject) => {
    const timer = setTimeout(() => reject(new Error(`kerf serve did not start: ${err}`)), 20000);
    proc.stderr.on('data', (d) => {
      err += d;
      const m = /serving .* at (http:\/\/[0-9.:]+\/)/.exec(err);
      if (m) {
        clearTimeout(timer);
        resolve({
          url: m[1],
          proc,
          log: () => err,
          stop: () => new Promise((res) => {
            if (proc.exitCode !== null || proc.signalCode !== null) return res();
            proc.once('exit', res);
            proc.kill('SIGTERM');
          }),
        });
      }
    });
    proc.once('exit', (code) => { clearTimeout(timer); reject(new Error(`kerf serve exited ${code}: ${err}`)); });
  });
}
