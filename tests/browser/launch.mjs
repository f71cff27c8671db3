// Starts the system Chromium for the browser tests, the same way for every harness.
//
// A fresh machine's first Chromium start can take well over puppeteer's default 30 s (the
// font cache is built then, and `cargo test` runs other tests beside it on few cores), so the
// start may take up to two minutes and is tried three times before the harness gives up with
// Chromium's own error. A call to the started browser that gets no answer within three minutes
// fails (the test fails, naming it, instead of stalling the run). `--disable-dev-shm-usage`
// keeps Chromium off a small /dev/shm (containers).
import puppeteer from 'puppeteer-core';

export const CHROMIUM = process.env.RTCDOC_CHROMIUM || '/usr/bin/chromium';

const BASE_ARGS = [
  '--no-sandbox',
  '--disable-gpu',
  '--no-first-run',
  '--disable-background-networking',
  '--disable-dev-shm-usage',
];

/** A headless Chromium with BASE_ARGS and `extra`; three tries of up to 120 s each. */
export async function launchChromium(extra = []) {
  let last;
  for (let attempt = 1; attempt <= 3; attempt++) {
    try {
      return await puppeteer.launch({
        executablePath: CHROMIUM,
        headless: true,
        args: [...BASE_ARGS, ...extra],
        timeout: 120000,
        protocolTimeout: 180000,
      });
    } catch (e) {
      last = e;
      process.stderr.write(`chromium start ${attempt}/3 failed: ${e.message}\n`);
    }
  }
  throw last;
}
