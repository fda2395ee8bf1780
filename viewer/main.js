// The viewer page: loads a recording (file picker, drag and drop, or
// ?recording=URL), plays it (play/pause, scrub, speed), and shows chosen
// worlds side by side or overlaid. URL parameters, for links and tests:
//   recording=URL   load this file (XMLHttpRequest: works from file:// pages
//                   in browsers that allow it, e.g. chromium --allow-file-access-from-files)
//   time=S          show the frame at S seconds, paused
//   worlds=0,2      recorded worlds to show (indices into the file's `world`)
//   layout=side|overlay
//   size=480x320    a fixed view size in CSS pixels (else the window's): a
//                   screenshot then does not depend on how the browser sized
//                   its window when the page was laid out
//   bare=1          the 3D view alone, no controls
// Once a frame is drawn, #viewer-state holds JSON of each body's projected
// centre of mass (page pixels), colour and shape, the count of each kind of
// shape drawn, and the title ends in "ready".
"use strict";

(function () {
  var params = new URLSearchParams(window.location.search);
  var $ = function (id) { return document.getElementById(id); };
  var view = null, recording = null, playing = false, lastTick = 0, currentTime = 0;

  function status(text, isError) {
    $("status").textContent = text;
    $("status").className = isError ? "error" : "";
  }

  function chosenSlots(r) {
    var text = params.get("worlds");
    if (!text) return r.worldIndex.map(function (w, i) { return i; }).slice(0, 8);
    return text.split(",").map(Number).filter(function (i) { return i >= 0 && i < r.worlds; });
  }

  function publish() {
    $("viewer-state").textContent = JSON.stringify({
      scene: recording.scene, time: currentTime, frame: view.frame,
      frameTime: recording.time[view.frame], background: "#" + ManyworldsView.BACKGROUND.toString(16),
      canvas: view.renderer.domElement.getBoundingClientRect(),
      bodies: view.projectedBodies(), shapes: view.drawnShapes(),
      recordedShapes: recording.hasShapes(),
    });
    document.title = "manyworlds viewer: " + (recording.scene || "recording") + " ready";
  }

  function showTime(seconds) {
    currentTime = Math.min(Math.max(seconds, recording.time[0]), recording.time[recording.frames - 1]);
    var frame = recording.frameAt(currentTime);
    view.setFrame(frame);
    $("scrub").value = String(frame);
    $("clock").textContent = recording.time[frame].toFixed(3) + " s, frame " + frame + " / " +
                             (recording.frames - 1);
    publish();
  }

  function tick(now) {
    if (!playing) return;
    var elapsed = lastTick ? (now - lastTick) / 1000 : 0;
    lastTick = now;
    var next = currentTime + elapsed * Number($("speed").value);
    if (next > recording.time[recording.frames - 1]) next = recording.time[0];  // loop
    showTime(next);
    window.requestAnimationFrame(tick);
  }

  function setPlaying(on) {
    playing = on && recording !== null;
    $("play").textContent = playing ? "Pause" : "Play";
    lastTick = 0;
    if (playing) window.requestAnimationFrame(tick);
  }

  function open(buffer, label) {
    try {
      recording = ManyworldsRecording.fromBuffer(buffer);
    } catch (e) {
      status(label + ": " + e.message, true);
      return;
    }
    if (!view) view = new ManyworldsView.View(THREE, $("view"));
    var slots = chosenSlots(recording);
    view.show(recording, slots, params.get("layout") || $("layout").value);
    $("scrub").max = String(recording.frames - 1);
    status(label + ": " + (recording.scene || "scene") + ", " + recording.frames + " frames, " +
           recording.bodies + " bodies, worlds " +
           slots.map(function (i) { return recording.worldIndex[i]; }).join(", "));
    var time = params.get("time");
    showTime(time === null ? recording.time[0] : Number(time));
    setPlaying(time === null);
  }

  function openFile(file) {
    var reader = new FileReader();
    reader.onload = function () { open(reader.result, file.name); };
    reader.onerror = function () { status(file.name + ": cannot be read", true); };
    reader.readAsArrayBuffer(file);
  }

  function openUrl(url) {
    status("loading " + url);
    var request = new XMLHttpRequest();
    request.open("GET", url);
    request.responseType = "arraybuffer";
    request.onload = function () {
      // file:// answers with status 0.
      if (request.status === 200 || (request.status === 0 && request.response)) open(request.response, url);
      else status(url + ": HTTP " + request.status, true);
    };
    request.onerror = function () { status(url + ": cannot be loaded (from file:// pages start chromium with --allow-file-access-from-files, or use a local http server)", true); };
    request.send();
  }

  $("file").addEventListener("change", function (event) {
    if (event.target.files.length) openFile(event.target.files[0]);
  });
  document.addEventListener("dragover", function (event) { event.preventDefault(); });
  document.addEventListener("drop", function (event) {
    event.preventDefault();
    if (event.dataTransfer.files.length) openFile(event.dataTransfer.files[0]);
  });
  $("play").addEventListener("click", function () { setPlaying(!playing); });
  $("scrub").addEventListener("input", function () {
    setPlaying(false);
    showTime(recording.time[Number($("scrub").value)]);
  });
  $("layout").addEventListener("change", function () {
    params.set("layout", $("layout").value);
    if (recording) {
      view.show(recording, chosenSlots(recording), $("layout").value);
      showTime(currentTime);
    }
  });
  // Headless browsers may size the window after the first frame: what was
  // published must follow.
  window.addEventListener("resize", function () {
    if (!view) return;
    view.resize();
    if (recording) publish();
  });

  var size = /^(\d+)x(\d+)$/.exec(params.get("size") || "");
  if (size) {
    $("view").style.right = $("view").style.bottom = "auto";
    $("view").style.width = size[1] + "px";
    $("view").style.height = size[2] + "px";
  }
  if (params.get("layout")) $("layout").value = params.get("layout");
  if (params.get("recording")) openUrl(params.get("recording"));
  else status("open a recording (.npz): the file button, or drop it here");
})();
