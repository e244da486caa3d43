// Tutorial 10 site: the live embeds. Each <div class="live" data-src="web/STAGE/index.html"> holds
// the still frame the build rendered (figure.render) and a bar with a "Run live" button; the button
// puts the stage's web page (make web: the same Tutorial10.cpp and shaders compiled to WebAssembly
// and WebGL2) in an iframe in place of the picture. Once the page has drawn its first frame, the
// controls are generated from the page's own list of live options, Module.t10Options() (names,
// ranges, choices: the stage's command-line options), and every change goes through Module.t10Set,
// the same parser and checks as the command line. Where the browser lacks WebGL2 or float render
// targets, or the site is opened from the disk, the picture stays and the bar says why.
// Once it runs, "Edit the shaders" opens the shader editor (setupEditor: issue 52).
// State for tests: each .live element's data-state is idle, loading, rendered, error or unavailable;
// data-editor is open (loading), ready (the work applied), closed or error.
(function () {
  "use strict";

  var POLL_MS = 50;
  var LOAD_TIMEOUT_MS = 120000;

  // What this browser lacks for the stages' chain, or "" when it has everything.
  function missingFeature() {
    if (location.protocol === "file:")
      return "The live version needs the site served over HTTP (make site-serve): a page opened from the disk may not load WebAssembly.";
    var canvas = document.createElement("canvas");
    var gl = null;
    try { gl = canvas.getContext("webgl2"); } catch (e) { gl = null; }
    if (!gl) return "This browser has no WebGL2, so the stages cannot run in it: the picture above is the frame the build rendered.";
    var floats = gl.getExtension("EXT_color_buffer_float");
    var lose = gl.getExtension("WEBGL_lose_context");
    if (lose) lose.loseContext();
    if (!floats)
      return "This browser's WebGL2 cannot render into floating-point textures (EXT_color_buffer_float), which the HDR chain needs: the picture above is the frame the build rendered.";
    return "";
  }

  function setState(live, state, message) {
    live.setAttribute("data-state", state);
    var note = live.querySelector(".live-note");
    if (note && message !== undefined) note.textContent = message;
  }

  // The size the stage renders at: the embed's width in device pixels, at most 1280, 16:9.
  function frameSize(live) {
    var width = live.querySelector("figure").getBoundingClientRect().width || 640;
    var w = Math.max(64, Math.min(1280, Math.round(width * (window.devicePixelRatio || 1))));
    w -= w % 2;
    return w + "x" + Math.round(w * 9 / 16);
  }

  function pageOf(frame) {
    try { return frame.contentWindow && frame.contentWindow.document && frame.contentWindow.document.body; }
    catch (e) { return null; }  // another origin: never the case for the site's own pages
  }

  // Waits until the page's dataset.t10 leaves "loading" (or frames moves past `after`, when given).
  function waitFor(frame, after, done) {
    var started = performance.now();
    (function poll() {
      var body = pageOf(frame);
      var state = body && body.dataset.t10;
      var frames = body ? Number(body.dataset.t10Frames || 0) : 0;
      if (state === "error") return done("error", body);
      if (state === "rendered" && (after === null || frames > after)) return done("rendered", body);
      if (performance.now() - started > LOAD_TIMEOUT_MS) return done("timeout", body);
      setTimeout(poll, POLL_MS);
    })();
  }

  // Which of the page's options get a control: the stage's own settings (the options the stage adds
  // itself, CLI11's top level: the exercises' white point, bloom, passes, luminance format) and the
  // buffer shown (--view). The other groups (context, frames, scene files, outputs, benchmark) are
  // about the process, not the picture.
  function wanted(option) {
    if (option.live !== undefined) return !!option.live;
    if (option.name === "view") return true;
    return (option.group === "" || option.group === undefined) && option.name !== "help" && option.name !== "version";
  }

  // The page's list (Module.t10Options(): the stage's command-line options as CLI11 describes them)
  // as controls need it: type flag, choice, int or float, with the range or the choices CLI11's
  // type text gives ("FLOAT:from 0.05 to 2", "INT:from 0 to 16", "TEXT:{r16,r16f}"), and for
  // --view the views the page says WebGL2 can show.
  function normalise(data) {
    var out = [];
    ((data && data.options) || []).forEach(function (raw) {
      // CLI11's spelling of a negated flag ("no-bloom{false}") is the option's name plus its value.
      var o = Object.assign({}, raw, { name: String(raw.name || "").replace(/\{[^}]*\}$/, "") });
      if (!/^[a-z][a-z0-9-]*$/.test(o.name) || !wanted(o)) return;
      var text = o.typeText || (typeof o.type === "string" && /^[A-Z]/.test(o.type) ? o.type : "");
      var option = { name: o.name, help: o.description || o.help || "", type: o.type,
                     min: o.min, max: o.max, choices: o.choices, value: o.value,
                     default: o["default"] === undefined || o["default"] === null ? "" : String(o["default"]) };
      if (o.flag === true || o.type === "flag") {
        option.type = "flag";
        option["default"] = "0";
        // Given on the command line or the URL: "" (the bare flag), "1" or "true" is on.
        option.value = o.value === undefined || o.value === null ? "0" : (o.value === "" || o.value === "1" || o.value === "true") ? "1" : "0";
        return out.push(option);
      }
      var range = /from\s+(-?[\d.]+)\s+to\s+(-?[\d.]+)/.exec(text) || /\[\s*(-?[\d.]+)\s*-\s*(-?[\d.]+)\s*\]/.exec(text);
      if (range && option.min === undefined) { option.min = Number(range[1]); option.max = Number(range[2]); }
      var set = /\{([^}]*)\}/.exec(text);
      if (set && !option.choices) option.choices = set[1].split(",");
      if (o.name === "view" && data.views) {
        option.choices = data.views;
        if (option.value === undefined && data.view) option.value = data.view;
        if (!option["default"]) option["default"] = data.views[0];
      }
      if (!/^(choice|int|float)$/.test(option.type || ""))
        option.type = option.choices ? "choice" : /^INT/.test(text) ? "int" : /^FLOAT/.test(text) ? "float" : "text";
      if (option.value === undefined || option.value === null) option.value = option["default"];
      // A choice without a default (CLI11 has none for an option that runs a function): the stages
      // list their default first ("r16 ... (the default) or r16f").
      if (option.type === "choice" && !option.value) option.value = option.choices[0];
      if (option.type === "choice" && !option["default"]) option["default"] = option.choices[0];
      // Only the choices the page can honour are listed (extras' --key without exact in a browser):
      // one left is nothing to choose.
      if (option.type === "choice" && option.choices.length < 2) return;
      option.value = String(option.value);
      out.push(option);
    });
    return out;
  }

  function options(frame) {
    var module = frame.contentWindow.Module;
    if (!module || typeof module.t10Options !== "function") return [];
    var data = module.t10Options();
    return normalise(typeof data === "string" ? JSON.parse(data) : data);
  }

  function isOn(value) { return value === "1" || value === "true"; }

  // An option's name in words ("white-point" -> "White point"): the control's label; the command-line
  // flag and the option's help are its hint (aria-describedby), shown beside it.
  function words(name) {
    var text = name.replace(/-/g, " ");
    return text.charAt(0).toUpperCase() + text.slice(1);
  }

  var controlCount = 0;

  function makeControl(option, apply, stage) {
    var row = document.createElement("div");
    row.className = "live-control";
    var id = "live-" + stage + "-" + option.name + "-" + (++controlCount);
    var name = document.createElement("label");
    name.className = "live-name";
    name.htmlFor = id;
    name.textContent = words(option.name);
    var hint = document.createElement("code");
    hint.className = "live-flag";
    hint.id = id + "-hint";
    hint.textContent = "--" + option.name;
    if (option.help) hint.title = option.help;
    var help = document.createElement("span");
    help.className = "visually-hidden";
    help.id = id + "-help";
    help.textContent = option.help ? ": " + option.help : "";
    var value = option.value;
    var input, shown = null;
    if (option.type === "flag") {
      input = document.createElement("input");
      input.type = "checkbox";
      input.checked = isOn(value);
      row.appendChild(input);
      row.appendChild(name);
      row.appendChild(hint);
      input.addEventListener("change", function () { apply(option.name, input.checked ? "1" : "0", input); });
    } else if (option.type === "choice") {
      input = document.createElement("select");
      option.choices.forEach(function (choice) {
        var item = document.createElement("option");
        item.value = item.textContent = choice;
        input.appendChild(item);
      });
      input.value = value;
      row.appendChild(name);
      row.appendChild(hint);
      row.appendChild(input);
      input.addEventListener("change", function () { apply(option.name, input.value, input); });
    } else if ((option.type === "float" || option.type === "int") && option.min !== undefined) {
      input = document.createElement("input");
      input.type = "range";
      input.min = option.min;
      input.max = option.max;
      // A round step (0.01 for 0.05..2) so that values like 0.8 are on the slider.
      input.step = option.type === "int" ? 1 : Math.pow(10, Math.floor(Math.log10((option.max - option.min) / 100)));
      input.value = value;
      shown = document.createElement("output");
      shown.htmlFor = id;
      shown.textContent = value;
      row.appendChild(name);
      row.appendChild(hint);
      row.appendChild(input);
      row.appendChild(shown);
      input.addEventListener("input", function () { shown.textContent = input.value; });
      input.addEventListener("change", function () {
        var v = option.type === "int" ? String(Math.round(Number(input.value))) : String(Number(Number(input.value).toPrecision(3)));
        shown.textContent = v;
        apply(option.name, v, input);
      });
    } else {
      return null;  // no control for a free-text option
    }
    input.id = id;
    input.setAttribute("aria-describedby", hint.id + " " + help.id);
    row.appendChild(help);
    input.setAttribute("data-option", option.name);
    input.setAttribute("data-default", String(option.default || ""));
    row.setAttribute("data-type", option.type);
    return row;
  }

  // A control shows `value` (a refused change puts the accepted one back).
  function showValue(input, value) {
    if (input.type === "checkbox") input.checked = isOn(value);
    else input.value = value;
    var shown = input.parentNode && input.parentNode.querySelector("output");
    if (shown) shown.textContent = value;
  }

  // "Frame 7 drawn with --white-point 0.32 --blur-passes 0.": the page's record of its last frame,
  // the controls' options among its arguments (the last of each name, as the parser takes them).
  function drawnWith(frame, list) {
    var drawn = frame.contentWindow.Module.t10Drawn();
    var names = {}, given = {}, order = [];
    list.forEach(function (option) { names[option.name] = true; });
    (drawn.args || []).forEach(function (arg) {
      var m = /^--([^=]+)(?:=(.*))?$/.exec(arg);
      if (!m || !names[m[1]]) return;
      if (!(m[1] in given)) order.push(m[1]);
      given[m[1]] = m[2] === undefined ? "" : m[2];
    });
    var text = order.map(function (name) { return "--" + name + (given[name] ? " " + given[name] : ""); }).join(" ");
    return "Frame " + drawn.frames + " drawn with " + (text || "the defaults") + ".";
  }

  function buildControls(live, frame) {
    var box = live.querySelector(".live-controls");
    if (!box) return;
    var list;
    try { list = options(frame); }
    catch (e) { box.textContent = "The page's option list could not be read: " + e; return; }
    var status = document.createElement("p");
    status.className = "live-control-status";
    // Each change is handed to the page at once, in the order the reader makes them (the page
    // rebuilds the stage inside t10Set), so the last one wins; one wait covers the changes made
    // meanwhile, and the status line then names what the frame was drawn with (Module.t10Drawn).
    var waiting = false;
    var accepted = {};
    list.forEach(function (option) { accepted[option.name] = option.value; });
    function apply(name, value, input) {
      var body = pageOf(frame);
      if (!body) return;
      var before = Number(body.dataset.t10Frames || 0);
      var error = frame.contentWindow.Module.t10Set(name, value);
      if (error) {
        // Refused: the frame and the control keep the value the page drew with.
        showValue(input, accepted[name]);
        status.textContent = error.replace(/\nRun with --help.*$/, "") + " The frame keeps --" + name + " " + accepted[name] + ".";
        status.className = "live-control-status live-control-error";
        return;
      }
      accepted[name] = value;
      if (waiting) return;
      waiting = true;
      live.setAttribute("data-state", "loading");
      waitFor(frame, before, function (state, page) {
        waiting = false;
        if (state !== "rendered") return failed(live, frame, state, page);
        status.className = "live-control-status" + (page.dataset.t10Notice ? " live-control-error" : "");
        status.textContent = drawnWith(frame, list) + (page.dataset.t10Notice ? " " + page.dataset.t10Notice : "");
        live.setAttribute("data-state", "rendered");
      });
    }
    list.forEach(function (option) {
      var control = makeControl(option, apply, live.getAttribute("data-stage"));
      if (control) box.appendChild(control);
    });
    if (!box.children.length) {
      box.textContent = "This stage has no settings to change live.";
      return;
    }
    box.appendChild(status);
  }

  // "Edit the shaders" (issue 52): shown once the embed runs, when its page offers the shader contract
  // (Module.t10Shaders and t10SetShader); it opens the shader editor (assets/editor/editor.js, CodeMirror 5
  // from Debian's libjs-codemirror, which the site build copies in) in the panel under the controls.
  var EDITOR_BASE = "assets/editor/";

  function setupEditor(live, frame) {
    var box = live.querySelector(".live-editor");
    var module = frame.contentWindow && frame.contentWindow.Module;
    if (!box || !module || typeof module.t10Shaders !== "function" || typeof module.t10SetShader !== "function") return;
    var toggle = box.querySelector(".live-edit");
    var panel = box.querySelector(".live-editor-panel");
    // A restarted embed (the exercises' retry with another luminance format) gets a fresh editor over
    // its new page; the button keeps its one listener.
    live.t10EditFrame = frame;
    live.t10EditorOpened = null;
    panel.textContent = "";
    panel.hidden = true;
    toggle.setAttribute("aria-expanded", "false");
    box.hidden = false;
    if (toggle.t10Bound) return;
    toggle.t10Bound = true;
    toggle.addEventListener("click", function () {
      var open = toggle.getAttribute("aria-expanded") !== "true";
      toggle.setAttribute("aria-expanded", open ? "true" : "false");
      panel.hidden = !open;
      live.setAttribute("data-editor", open ? "open" : "closed");
      if (!open || live.t10EditorOpened) {
        if (open) live.t10EditorOpened.then(function (editor) {
          if (editor) { editor.cm.refresh(); live.setAttribute("data-editor", "ready"); }
        });
        return;
      }
      var current = live.t10EditFrame;
      live.t10EditorOpened = loadScript(EDITOR_BASE + "editor.js").then(function () {
        return window.T10Editor.create({
          container: panel, stageBase: live.getAttribute("data-src").replace(/index\.html$/, ""),
          codemirror: EDITOR_BASE, css: EDITOR_BASE + "editor.css",
          stepLink: function (step) { return document.getElementById("step-" + step) ? "#step-" + step : null; },
          module: function () { return current.contentWindow && current.contentWindow.Module; },
          frames: function () { var body = pageOf(current); return body ? Number(body.dataset.t10Frames || 0) : 0; }
        });
      }).then(function (editor) {
        live.t10Editor = editor;
        return editor.ready.then(function () { live.setAttribute("data-editor", "ready"); return editor; });
      }, function (error) {
        if (!panel.querySelector(".t10-editor-status")) panel.textContent = "The shader editor could not start: " + error.message;
        live.setAttribute("data-editor", "error");
        return null;
      });
    });
  }

  function loadScript(url) {
    return new Promise(function (resolve, reject) {
      if (window.T10Editor) return resolve();
      var script = document.createElement("script");
      script.src = url;
      script.onload = function () { resolve(); };
      script.onerror = function () { reject(new Error(url + " could not be loaded")); };
      document.head.appendChild(script);
    });
  }

  function failed(live, frame, state, page) {
    var error = page && page.ownerDocument.getElementById("t10-error");
    var message = state === "timeout" ? "The live page did not draw a frame within " + LOAD_TIMEOUT_MS / 1000 + " s."
        : "The live page reports: " + ((error && error.textContent) || "an error without a message") + ".";
    live.classList.remove("live-running");
    if (frame.parentNode) frame.parentNode.removeChild(frame);
    var box = live.querySelector(".live-controls");
    if (box) box.textContent = "";
    var editor = live.querySelector(".live-editor");
    if (editor) editor.hidden = true;
    setState(live, "error", message + " The picture above is the frame the build rendered.");
    // After a lost WebGL context a fresh page gets a fresh context: offered from the same button.
    if (page && page.dataset.t10Lost) {
      var again = live.querySelector(".live-start"), hidden = again.querySelector(".visually-hidden");
      again.textContent = "Run it live again";
      if (hidden) again.appendChild(hidden); // the stage's name, which tells the embeds' buttons apart
      again.hidden = false;
      live.setAttribute("data-state", "idle");
    }
    // Without EXT_texture_norm16 (no GL_R16 in this WebGL2) the exercises can still run with step 40's
    // R16F luminance texture: offered, never switched to silently.
    var retry = live.getAttribute("data-retry-args");
    if (retry && /norm16/i.test(message) && live.getAttribute("data-args") !== retry) {
      var button = live.querySelector(".live-start");
      button.textContent = "Run it with ?" + retry + " instead";
      button.hidden = false;
      live.setAttribute("data-args", retry);
      live.setAttribute("data-state", "idle");
    }
  }

  function start(live) {
    if (live.getAttribute("data-state") !== "idle") return;
    var figure = live.querySelector("figure");
    var picture = figure.querySelector("a, img");
    var frame = document.createElement("iframe");
    var query = "size=" + frameSize(live) + (live.getAttribute("data-args") ? "&" + live.getAttribute("data-args") : "");
    frame.src = live.getAttribute("data-src") + "?" + query;
    frame.title = "The stage " + live.getAttribute("data-stage") + " running live (WebGL2)";
    frame.className = "live-frame";
    frame.setAttribute("allow", "fullscreen");
    var started = performance.now();
    setState(live, "loading", "Loading " + live.getAttribute("data-size-text") + " and compiling the shaders ...");
    // The stage's page stands alone with a margin and a status line; in the embed only its canvas shows,
    // filling the frame (the page is the site's own, so its document can be styled from here).
    frame.addEventListener("load", function () {
      var doc = frame.contentDocument;
      if (!doc || !doc.head) return;
      var style = doc.createElement("style");
      style.textContent = "html, body { margin: 0 !important; padding: 0 !important; background: #000 !important; overflow: hidden; }" +
          " #t10-status { display: none !important; }" +
          " canvas { display: block; width: 100% !important; height: auto !important; max-width: none !important; }" +
          " canvas:focus-visible { outline: 3px solid #ffbf47 !important; outline-offset: -3px; }";
      doc.head.appendChild(style);
      // Escape leaves the frame for the embed's controls (Tab and Shift+Tab leave it too: the page
      // keeps emscripten's GLFW from taking Tab).
      // A lost WebGL context (the page stopped: index.html.in) is said in the embed's status line.
      frame.contentWindow.addEventListener("t10contextlost", function () {
        if (live.getAttribute("data-state") === "rendered") failed(live, frame, "error", pageOf(frame));
      });
      frame.contentWindow.addEventListener("keydown", function (event) {
        if (event.key !== "Escape") return;
        var next = live.querySelector(".live-controls input, .live-controls select") || live.querySelector(".live-note");
        if (next) next.focus();
      });
    });
    figure.insertBefore(frame, picture);
    live.classList.add("live-loading");
    waitFor(frame, null, function (state, page) {
      live.classList.remove("live-loading");
      if (state !== "rendered") return failed(live, frame, state, page);
      var seconds = (performance.now() - started) / 1000;
      live.setAttribute("data-first-frame-ms", String(Math.round(seconds * 1000)));
      live.classList.add("live-running");
      setState(live, "rendered", "Live: first frame after " + seconds.toFixed(1) +
               " s in this browser. Drag to look around, scroll to zoom, WASD and Q/E to move (with the frame focused;" +
               " Tab or Escape leaves it).");
      buildControls(live, frame);
      setupEditor(live, frame);
      // Started from its button, the reader's focus waited on the status line: it moves to the frame,
      // whose keys move the camera.
      var note = live.querySelector(".live-note");
      if (note && document.activeElement === note) {
        var canvas = frame.contentDocument && frame.contentDocument.getElementById("canvas");
        if (canvas) canvas.focus();
      }
    });
  }

  function setup() {
    var embeds = document.querySelectorAll(".live[data-src]");
    if (!embeds.length) return;
    var missing = missingFeature();
    Array.prototype.forEach.call(embeds, function (live) {
      var button = live.querySelector(".live-start");
      if (missing) {
        if (button) button.hidden = true;
        setState(live, "unavailable", missing);
        return;
      }
      setState(live, "idle");
      var note = live.querySelector(".live-note");
      if (note) note.setAttribute("tabindex", "-1");
      // The button disappears when pressed: the focus goes to the status line, which says what happens.
      if (button) button.addEventListener("click", function () {
        var focused = document.activeElement === button;
        button.hidden = true;
        start(live);
        if (focused && note) note.focus();
      });
    });
  }

  // For tests and readers who want every embed running: ?live=all starts them all.
  window.t10Live = {
    // The options the controls of an embed were made from (for tests).
    options: function (stage) {
      var frame = document.querySelector(".live[data-stage='" + stage + "'] iframe.live-frame");
      return frame ? options(frame) : [];
    },
    // One embed, by its stage's name (the button does the same).
    start: function (stage) {
      var live = document.querySelector(".live[data-stage='" + stage + "'][data-state='idle']");
      if (!live) return false;
      var button = live.querySelector(".live-start");
      if (button) button.hidden = true;
      start(live);
      return true;
    },
    // Every embed not yet started (?live=all does this on load).
    startAll: function () {
      Array.prototype.forEach.call(document.querySelectorAll(".live[data-state='idle']"), function (live) {
        var button = live.querySelector(".live-start");
        if (button) button.hidden = true;
        start(live);
      });
    }
  };

  function init() {
    setup();
    if (/[?&]live=all\b/.test(location.search)) window.t10Live.startAll();
  }
  if (document.readyState === "loading") document.addEventListener("DOMContentLoaded", init);
  else init();
})();
