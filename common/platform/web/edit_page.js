// A stage's page with ?edit=1 (issue 52): the shader editor (../editor/editor.js, CodeMirror 5 from
// Debian's libjs-codemirror, both copied into out/web/editor/ by cmake/T10Web.cmake) under the canvas,
// over this stage's shaders through the page's contract (Module.t10Shaders, t10SetShader, t10Check).
// Linked into every stage's .js as --post-js; without ?edit=1 it does nothing.
(function () {
  "use strict";
  if (typeof document === "undefined" || !new URLSearchParams(location.search).has("edit")) return;
  var box = document.createElement("section");
  box.id = "t10-editor";
  box.setAttribute("aria-label", "Shader editor");
  // Under the canvas and its status line (and the reload button a lost WebGL context shows), so that
  // what the page says stays next to its frame.
  var above = document.getElementById("t10-reload") || document.getElementById("canvas");
  above.parentNode.insertBefore(box, above.nextSibling);
  // emscripten's GLFW listens to the window's keys in the capturing phase (the camera's W A S D ...) and
  // cancels Backspace and Tab there, which CodeMirror then ignores: Backspace would do nothing in the
  // text. Registered before GLFW's (this file runs before the stage's main), this listener keeps the
  // editor's keys from GLFW and hands those of the text to CodeMirror itself (its own listener, on the
  // text, is not reached after stopImmediatePropagation). Tab too (the page's own listener leaves Tab in
  // the editor to this one): in the text it indents, and Escape, then Tab, moves on, as in the site's
  // embeds (editor.js; no keyboard trap); on the editor's buttons it moves on.
  ["keydown", "keypress", "keyup"].forEach(function (type) {
    var trigger = { keydown: "triggerOnKeyDown", keypress: "triggerOnKeyPress", keyup: "triggerOnKeyUp" }[type];
    window.addEventListener(type, function (event) {
      if (!event.target || !event.target.closest || !box.contains(event.target)) return;
      event.stopImmediatePropagation();
      var text = event.target.closest(".CodeMirror");
      if (text && text.CodeMirror) text.CodeMirror[trigger](event);
    }, true);
  });
  var started = false;
  function start() {
    if (started || document.body.dataset.t10 !== "rendered") return;
    started = true;
    var script = document.createElement("script");
    script.src = "../editor/editor.js";
    script.onload = function () {
      window.T10Editor.create({
        container: box, module: function () { return window.Module; }, stageBase: "./",
        codemirror: "../editor/codemirror/", css: "../editor/editor.css",
        frames: function () { return Number(document.body.dataset.t10Frames || 0); }
      }).catch(function (error) { console.warn("t10 editor: " + error.message); });
    };
    script.onerror = function () {
      box.textContent = "The shader editor (../editor/editor.js) could not be loaded: make web copies it into out/web/editor/.";
    };
    document.head.appendChild(script);
  }
  new MutationObserver(start).observe(document.body, { attributes: true, attributeFilter: ["data-t10"] });
  start();
})();
