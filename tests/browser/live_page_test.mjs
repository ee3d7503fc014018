// The live page in a real browser (headless Chromium, driven over the DevTools protocol): it
// shows the session's image changing between passes, and a command typed in the page turns the
// view. Usage: node --experimental-websocket live_page_test.mjs RADIANT CHROMIUM
import { spawn } from "node:child_process";
import { mkdtempSync, rmSync, writeFileSync } from "node:fs";
import { tmpdir } from "node:os";
import { join } from "node:path";

const [radiant, chromium] = process.argv.slice(2);
const dir = mkdtempSync(join(tmpdir(), "radiant-live-"));
const children = [];
let failed = false;

function fail(message) {
  console.error("FAIL: " + message);
  failed = true;
  throw new Error(message);
}
const sleep = (ms) => new Promise((done) => setTimeout(done, ms));

// Waits until `pattern` appears in the child's stderr and returns its first group.
function stderrMatch(child, pattern, what, seconds = 60) {
  return new Promise((resolve, reject) => {
    let text = "";
    const timer = setTimeout(() => reject(new Error(`no ${what} after ${seconds} s; stderr: ${text}`)), seconds * 1000);
    child.stderr.on("data", (chunk) => {
      text += chunk;
      const m = text.match(pattern);
      if (m) {
        clearTimeout(timer);
        resolve(m[1]);
      }
    });
  });
}

// The browser's one page, driven over the DevTools protocol on a pipe (--remote-debugging-pipe:
// JSON messages ended by a zero byte, fd 3 to the browser, fd 4 from it), which needs no
// WebSocket client: evaluate(expression) returns the expression's value.
async function openPage(browser) {
  const [toBrowser, fromBrowser] = [browser.stdio[3], browser.stdio[4]];
  let next = 0, buffer = "";
  const pending = new Map();
  fromBrowser.on("data", (chunk) => {
    buffer += chunk;
    for (let end; (end = buffer.indexOf("\0")) >= 0; buffer = buffer.slice(end + 1)) {
      const message = JSON.parse(buffer.slice(0, end));
      if (pending.has(message.id)) {
        pending.get(message.id)(message);
        pending.delete(message.id);
      }
    }
  });
  const call = (method, params = {}, sessionId = undefined) => {
    const id = ++next;
    toBrowser.write(JSON.stringify({ id, method, params, sessionId }) + "\0");
    return new Promise((resolve) => pending.set(id, resolve));
  };
  let page;
  for (let i = 0; i < 100 && !page; ++i) {
    const answer = await call("Target.getTargets");
    page = (answer.result?.targetInfos ?? []).find((t) => t.type === "page");
    if (!page) await sleep(100);
  }
  if (!page) fail("no page in the browser");
  const attached = await call("Target.attachToTarget", { targetId: page.targetId, flatten: true });
  const sessionId = attached.result?.sessionId ?? fail("cannot attach to the page: " + JSON.stringify(attached));
  return {
    async evaluate(expression) {
      const answer = await call("Runtime.evaluate", { expression, awaitPromise: true, returnByValue: true }, sessionId);
      if (answer.error || answer.result.exceptionDetails) fail("evaluate " + expression + ": " + JSON.stringify(answer));
      return answer.result.result.value;
    },
  };
}

// The page's state and its image's pixels, read from a canvas (the image is loaded by then).
const snapshot = `(async () => {
  const image = document.getElementById("image");
  if (!image || !image.src) return null;
  const generation = Number(image.dataset.generation), status = document.getElementById("status").textContent;
  const src = image.src;  // set together with the generation
  try {
    await image.decode();  // the image of the src just set, not the one still on screen
  } catch (e) {
    return null;  // replaced by a newer pass while loading
  }
  if (image.src !== src) return null;  // a newer pass arrived while decoding: its pixels are not this generation's
  const canvas = document.createElement("canvas");
  canvas.width = image.naturalWidth;
  canvas.height = image.naturalHeight;
  const context = canvas.getContext("2d");
  context.drawImage(image, 0, 0);
  return { generation, status,
           width: image.naturalWidth, pixels: Array.from(context.getImageData(0, 0, canvas.width, canvas.height).data).join(",") };
})()`;

async function waitFor(page, test, what, seconds = 120) {
  for (let waited = 0; waited < seconds * 1000; waited += 100) {
    const s = await page.evaluate(snapshot);
    if (s && test(s)) return s;
    await sleep(100);
  }
  fail("timed out waiting for " + what);
}

try {
  // A white room around the camera (saturated white) with a black ball in front, on one thread:
  // 64 samples per pixel take seconds, in seven passes, so the page (polling four times a second)
  // sees some, and a turn moves the ball.
  const scene = join(dir, "room.scene");
  writeFileSync(scene, "@camera\nposition 0 0 0\ndirection 0 0 -1\nup 0 1 0\n@light point\ncolor 255 255 255\n" +
    "position 0 3 0\n@sphere\ncenter 0 0 0\nradius 10\nkd 1\n@sphere\ncenter 1 0 -5\nradius 1.5\nkd 0\n");
  const session = spawn(radiant, ["session", "-o", join(dir, "view.png"), "--serve", "127.0.0.1:0", "--width=48",
    "--height=48", "--spp=64", "--mode=path", "--max-depth=1000", "--threads=1", scene], { stdio: ["pipe", "pipe", "pipe"] });
  children.push(session);
  let written = 0;
  session.stdout.on("data", (chunk) => { written += (String(chunk).match(/^wrote /gm) || []).length; });
  const url = await stderrMatch(session, /watch the render at (http:\/\/\S+)/, "page address");

  const browser = spawn(chromium, ["--headless=new", "--no-sandbox", "--disable-gpu", "--remote-debugging-pipe",
    "--user-data-dir=" + join(dir, "profile"), url], { stdio: ["ignore", "ignore", "ignore", "pipe", "pipe"] });
  children.push(browser);
  const page = await openPage(browser);

  // Two passes of the first view, seen as two different images. The image a generation names is
  // the newest when it is fetched, which may already be a later pass's: wait for one that differs.
  const first = await waitFor(page, (s) => s.generation >= 1 && s.width === 48, "the first pass");
  await waitFor(page, (s) => s.generation > first.generation && s.pixels !== first.pixels,
                "a later pass showing a different image");
  const done = await waitFor(page, (s) => s.status.includes(": done,"), "the first view to finish");
  if (!done.status.includes("64 of 64 spp")) fail("status of a finished view: " + done.status);

  // A command typed in the page: the session renders the turned view and the page shows it.
  await page.evaluate(`(() => { const c = document.getElementById("command"); c.value = "turn 0 10 0";
    document.getElementById("form").requestSubmit(); return true; })()`);
  const turned = await waitFor(page, (s) => s.generation > done.generation && s.status.includes(": done,"),
    "the turned view to finish");
  if (turned.pixels === done.pixels) fail(`the view did not turn: generation ${done.generation} "${done.status}" then ${turned.generation} "${turned.status}"`);
  if (written !== 2) fail(`the session wrote ${written} images, not 2`);

  session.stdin.end("quit\n");
  console.log("live page: passes and a command from the page seen in headless Chromium");
} catch (e) {
  if (!failed) console.error("FAIL: " + e.message);
  failed = true;
} finally {
  await Promise.all(children.map((child) => new Promise((done) => {
    if (child.exitCode !== null || child.signalCode !== null) return done();
    child.on("exit", done);
    child.kill("SIGKILL");
  })));
  rmSync(dir, { recursive: true, force: true, maxRetries: 5 });
}
process.exit(failed ? 1 : 0);
