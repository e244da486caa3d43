// The page's contract for editing a stage's shaders (every stage page: cmake/T10Web.cmake links this
// file with --post-js, so it runs inside the module's scope, beside its C halves in
// common/frame/src/loop/shader_edit_web.cpp). Tests, the site's editor and other tools drive it:
//   Module.t10Shaders()             -> [{file, source}]: the stage's shader files as the page compiles them
//   Module.t10SetShader(file, src)  -> Promise of {ok, errors: [{line, message}]}: `src` (a string, or
//       the file's bytes as a Uint8Array or ArrayBuffer) compiled through the page's GLSL ES translator;
//       ok: the stage runs it and the promise settles once the frame is redrawn; else each error on its
//       line of `src` (0: the file or the program as a whole) and the last good program keeps drawing.
//   Module.t10Check()               -> Promise of t10-grade's report for the shaders the page runs
//       (grader/page/page_check.cpp: score, failed_steps, steps[], checks[] with their mistakes and
//       estimates, not_judged[]: what the page cannot judge), or {error}.
// Nothing here throws or rejects: a wrong argument is an answer with ok false, like a compile error.
// After a lost WebGL context (index.html.in: Module.t10Lost says what happened) both answer at once with
// that message, without touching GL: nothing can be compiled or drawn until the page is reloaded.
(function () {
  'use strict';
  const maxNameLength = 255;

  function refusal(message, line) {
    return {ok: false, errors: [{line: line || 0, message: message}]};
  }

  // A JavaScript string is UTF-16: a lone surrogate half has no UTF-8 form (TextEncoder would silently
  // write U+FFFD in its place). Its line, or 0 when there is none.
  function loneSurrogateLine(text) {
    const lone = /[\uD800-\uDBFF](?![\uDC00-\uDFFF])|(?:^|[^\uD800-\uDBFF])[\uDC00-\uDFFF]/.exec(text);
    if (!lone) return 0;
    return text.slice(0, lone.index + 1).split('\n').length;
  }

  // The source's bytes, or a refusal.
  function bytesOf(file, source, maxBytes) {
    if (typeof source === 'string') {
      if (source.length > maxBytes) {
        return refusal(file + ': ' + source.length + ' characters is more than the ' + maxBytes +
                       ' bytes a shader may have here');
      }
      const line = loneSurrogateLine(source);
      if (line) return refusal('a lone UTF-16 surrogate (U+D800-U+DFFF): the text is not valid Unicode', line);
      return new TextEncoder().encode(source);
    }
    if (source instanceof ArrayBuffer) source = new Uint8Array(source);
    if (source instanceof Uint8Array) return source;
    return refusal('the source of ' + file + ' must be a string, a Uint8Array or an ArrayBuffer, not ' +
                   (source === null ? 'null' : typeof source));
  }

  // Settles once the page has drawn a frame after `framesBefore` ("rendered") or stopped ("error").
  function redrawn(framesBefore) {
    const body = document.body;
    const settled = () => body.dataset.t10 === 'error' ||
                          (body.dataset.t10 === 'rendered' && Number(body.dataset.t10Frames) > framesBefore);
    return new Promise((resolve) => {
      if (settled()) return resolve(body.dataset.t10);
      const watch = new MutationObserver(() => {
        if (!settled()) return;
        watch.disconnect();
        resolve(body.dataset.t10);
      });
      watch.observe(body, {attributes: true, attributeFilter: ['data-t10', 'data-t10-frames']});
    });
  }

  function setShader(file, source) {
    if (Module['t10Lost']) return Promise.resolve(refusal(Module['t10Lost']));
    if (typeof file !== 'string' || file.length === 0 || file.length > maxNameLength) {
      return Promise.resolve(refusal('the file must be one of the names Module.t10Shaders() lists'));
    }
    const bytes = bytesOf(file, source, _t10_shader_max_bytes());
    if (!(bytes instanceof Uint8Array)) return Promise.resolve(bytes);
    const buffer = _t10_shader_buffer(bytes.length);
    if (!buffer) return Promise.resolve(refusal(file + ': ' + bytes.length + ' bytes is more than a shader may have here'));
    HEAPU8.set(bytes, buffer); // HEAPU8 read after the allocation: memory may have grown
    const framesBefore = Number(document.body.dataset.t10Frames || 0);
    const answer = JSON.parse(ccall('t10_set_shader', 'string', ['string'], [file]));
    // A refused edit that was compiled and linked (a link error) rebuilt the stage with the previous
    // file: it too settles once that frame is drawn again.
    if (!answer.ok && document.body.dataset.t10 !== 'loading') return Promise.resolve(answer);
    return redrawn(framesBefore).then((state) => state === 'rendered' || !answer.ok ? answer : refusal(
        'the page stopped after the edit: ' + (document.getElementById('t10-error') || {}).textContent));
  }

  // The check runs at once (it renders t10-grade's cases in turn, then puts the page's settings back);
  // the promise settles once the page has drawn its own frame again.
  function check() {
    if (Module['t10Lost']) return Promise.resolve({error: Module['t10Lost']});
    const framesBefore = Number(document.body.dataset.t10Frames || 0);
    const report = JSON.parse(UTF8ToString(_t10_check()));
    if (report.error) return Promise.resolve(report);
    return redrawn(framesBefore).then(() => report);
  }

  Module['t10Check'] = () => new Promise((resolve) => {
    // After the current task: a caller's own redraw (t10SetShader's) is not held up by a check.
    setTimeout(() => {
      try {
        check().then(resolve);
      } catch (error) {
        resolve({error: 'the check could not run: ' + error});
      }
    }, 0);
  });
  Module['t10Shaders'] = () => JSON.parse(UTF8ToString(_t10_shaders()));
  Module['t10SetShader'] = (file, source) => {
    try {
      return setShader(file, source);
    } catch (error) {
      return Promise.resolve(refusal('the edit could not be applied: ' + error));
    }
  };
})();
