// The page `--serve` shows: the image, its samples, time and ETA, polled from /status, and (in a
// session) a command line posted to /command.
#pragma once

namespace radiant::cli {

inline constexpr const char* live_page_html = R"html(<!doctype html>
<html lang="en">
<head>
<meta charset="utf-8">
<title>radiant</title>
<style>
body { background: #222; color: #ddd; font: 14px sans-serif; margin: 1em; }
#image { display: block; max-width: 100%; image-rendering: pixelated; background: #111; min-height: 64px; }
#status { margin: 0.5em 0; font-family: monospace; }
#command { width: 30em; font-family: monospace; }
#log { font-family: monospace; white-space: pre-wrap; color: #aaa; }
</style>
</head>
<body>
<img id="image" alt="the render">
<div id="status">waiting for the first pass</div>
<form id="form" hidden>
<input id="command" autocomplete="off" placeholder="turn 0 10 0, set spp 256, render, help ...">
<button type="submit">send</button>
</form>
<div id="log"></div>
<script>
"use strict";
let shown = -1;
const image = document.getElementById("image"), status = document.getElementById("status");
const form = document.getElementById("form"), command = document.getElementById("command");
const log = document.getElementById("log");
function seconds(s) { return s < 0 ? "-" : s.toFixed(1) + " s"; }
async function poll() {
  try {
    const s = await (await fetch("/status", {cache: "no-store"})).json();
    form.hidden = !s.commands;
    if (s.generation !== shown && s.generation > 0) {
      shown = s.generation;
      image.src = "/image.png?g=" + s.generation;
    }
    image.dataset.generation = String(shown);
    status.textContent = s.name + ": " + s.state + ", " + s.samples + " of " + s.target + " spp, " +
        seconds(s.elapsed) + " elapsed, ETA " + seconds(s.eta);
  } catch (e) {
    status.textContent = "radiant is not answering (" + e + ")";
  }
  setTimeout(poll, 250);
}
form.addEventListener("submit", async (event) => {
  event.preventDefault();
  const text = command.value;
  command.value = "";
  const answer = await fetch("/command", {method: "POST", body: text});
  log.textContent = "> " + text + (answer.ok ? "" : "  (" + answer.status + " " + await answer.text() + ")") +
      "\n" + log.textContent;
});
poll();
</script>
</body>
</html>
)html";

}  // namespace radiant::cli
