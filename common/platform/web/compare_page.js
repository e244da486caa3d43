// The compare page of a student's web build (index.html?compare=1): linked into a student's module
// with --post-js (cmake/T10Student.cmake), so it runs inside the module's scope. Once the student's
// frame is rendered it loads the reference part's page (../<reference>/index.html) with the same
// settings in a frame beside it, reads both canvases and judges them with the golden test's own code
// and tolerance (t10_compare_rgba, compare_export.cpp beside this file, compiled into this module), then
// shows both frames, the difference heat-map, the verdict and the tolerance, and sets
// document.body.dataset.t10Verdict to "pass" or "fail". The metric is not repeated here.
// t10CompareReference (the reference stage's folder) is set by a --pre-js that CMake writes.
(function () {
  'use strict';
  const query = new URLSearchParams(location.search);
  if (!query.has('compare') || query.get('compare') === '0') return;
  const toleranceFile = '/t10/compare/reference.tolerance'; // where the build packages it
  const reference = typeof t10CompareReference === 'string' ? t10CompareReference : '';
  const timeoutMs = 180000;
  let section = null;

  function element(tag, attributes, text) {
    const e = document.createElement(tag);
    for (const [name, value] of Object.entries(attributes || {})) e.setAttribute(name, value);
    if (text !== undefined) e.textContent = text;
    return e;
  }

  function verdict(result, message) {
    const line = section.querySelector('#t10-verdict');
    line.textContent = message;
    line.className = 't10-verdict-' + result;
    document.body.dataset.t10Verdict = result;
  }

  // The page's state ("loading", "rendered", "error") as the platform sets it on a body.
  function whenSettled(body, what) {
    return new Promise((resolve, reject) => {
      const started = performance.now();
      const poll = () => {
        const state = body() && body().dataset.t10;
        if (state === 'rendered' || state === 'error') return resolve(state);
        if (performance.now() - started > timeoutMs) return reject(new Error(what + ' did not render within ' +
                                                                           timeoutMs / 1000 + ' s'));
        setTimeout(poll, 100);
      };
      poll();
    });
  }

  // The canvas' pixels, top row first, RGBA: both frames are read the same way.
  function pixelsOf(canvas) {
    const copy = element('canvas');
    copy.width = canvas.width;
    copy.height = canvas.height;
    const context = copy.getContext('2d');
    context.drawImage(canvas, 0, 0);
    return context.getImageData(0, 0, copy.width, copy.height);
  }

  function figure(caption, image) {
    const f = element('figure', {class: 't10-compare-frame'});
    const c = element('canvas', {width: image.width, height: image.height});
    c.getContext('2d').putImageData(image, 0, 0);
    f.append(c, element('figcaption', {}, caption));
    return f;
  }

  function stringAt(pointer) {
    let end = pointer;
    while (HEAPU8[end] !== 0) ++end;
    return new TextDecoder().decode(HEAPU8.subarray(pointer, end));
  }

  // The golden comparison, in the module: expected = the reference, actual = the student's.
  function judge(expected, actual) {
    const bytes = expected.width * expected.height * 4;
    const slots = [0, 1, 2].map(slot => Module._t10_compare_buffer(slot, bytes));
    const path = new TextEncoder().encode(toleranceFile + '\0');
    const pathSlot = Module._t10_compare_buffer(3, path.length);
    if (slots.includes(0) || !pathSlot) throw new Error('the frames are too large to compare (' + bytes + ' bytes)');
    HEAPU8.set(expected.data, slots[0]); // HEAPU8 read after the allocations: memory may have grown
    HEAPU8.set(actual.data, slots[1]);
    HEAPU8.set(path, pathSlot);
    const result = JSON.parse(stringAt(Module._t10_compare_rgba(expected.width, expected.height, pathSlot)));
    const heat = new ImageData(new Uint8ClampedArray(HEAPU8.slice(slots[2], slots[2] + bytes)),
                               expected.width, expected.height);
    return {result: result, heat: heat};
  }

  function show(frames, result) {
    const row = section.querySelector('.t10-compare-frames');
    row.replaceChildren(...frames);
    const t = result.tolerance;
    section.querySelector('#t10-compare-figures').textContent = result.summary;
    section.querySelector('#t10-tolerance').textContent =
      'Tolerance (tests/golden/' + reference + '.tolerance, the golden test\'s): a pixel fails when a channel ' +
      'differs by more than ' + t.threshold + ' of 255; at most ' + (t.maxFraction * 100) + '% of the pixels ' +
      'may fail; the mean difference may be at most ' + t.maxMean + ' of 255.';
    section.querySelector('#t10-tolerance-file').textContent = t.file;
  }

  async function compare() {
    const ownState = await whenSettled(() => document.body, 'your frame');
    if (ownState === 'error') {
      const message = (document.getElementById('t10-error') || {}).textContent || 'your program stopped';
      return verdict('fail', 'Fail: your program did not render: ' + message);
    }
    if (!reference) {
      return verdict('fail', 'No reference to compare with: the build could not tell which part this folder is ' +
                             '(name it partN, as make student PART=N does)');
    }
    const settings = new URLSearchParams(location.search);
    settings.delete('compare');
    const frame = element('iframe', {id: 't10-reference', title: 'the reference part',
                                     src: '../' + reference + '/index.html?' + settings.toString()});
    const canvas = document.getElementById('canvas');
    frame.style.width = Math.max(canvas.width, 320) + 40 + 'px';
    frame.style.height = Math.max(canvas.height, 180) + 160 + 'px';
    section.querySelector('.t10-compare-reference').append(frame);
    const referenceBody = () => frame.contentDocument && frame.contentDocument.body;
    const referenceState = await whenSettled(referenceBody, 'the reference ' + reference);
    if (referenceState === 'error') {
      const message = (frame.contentDocument.getElementById('t10-error') || {}).textContent || '';
      return verdict('fail', 'No verdict: the reference ' + reference + ' did not render in this browser: ' + message);
    }
    const expected = pixelsOf(frame.contentDocument.getElementById('canvas'));
    const actual = pixelsOf(canvas);
    if (expected.width !== actual.width || expected.height !== actual.height) {
      return verdict('fail', 'Fail: your frame is ' + actual.width + 'x' + actual.height + ', the reference\'s ' +
                             expected.width + 'x' + expected.height);
    }
    const {result, heat} = judge(expected, actual);
    if (result.error) return verdict('fail', 'No verdict: ' + result.error);
    frame.remove(); // its pixels are copied; the copies are shown with the heat-map
    show([figure('Your frame', actual), figure('Reference: ' + reference, expected),
          figure('Difference (largest channel difference x4: black none, red, yellow, white large)', heat)], result);
    verdict(result.passed ? 'pass' : 'fail',
            result.passed ? 'Pass: your frame matches ' + reference + ' within the golden test\'s tolerance'
                          : 'Fail: your frame differs from ' + reference + ' beyond the golden test\'s tolerance');
  }

  function start() {
    section = element('section', {id: 't10-compare'});
    section.append(element('h2', {}, 'Your frame against the reference'),
                   element('p', {id: 't10-verdict'}, 'Comparing: waiting for both frames...'),
                   element('p', {id: 't10-compare-figures'}),
                   element('div', {class: 't10-compare-frames'}),
                   element('div', {class: 't10-compare-reference'}),
                   element('p', {id: 't10-tolerance'}),
                   element('pre', {id: 't10-tolerance-file'}));
    const style = element('style', {}, '#t10-compare .t10-compare-frames { display: flex; flex-wrap: wrap; gap: 1em; }' +
      '#t10-compare figure { margin: 0; } #t10-compare canvas { max-width: 100%; }' +
      '#t10-compare iframe { border: 0; } #t10-tolerance-file { white-space: pre-wrap; font-size: 80%; }' +
      '.t10-verdict-pass { color: #176f2c; font-weight: bold; } .t10-verdict-fail { color: #b3261e; font-weight: bold; }');
    document.head.append(style);
    document.body.append(section);
    compare().catch(error => verdict('fail', 'No verdict: ' + error.message));
  }

  if (document.readyState === 'loading') document.addEventListener('DOMContentLoaded', start);
  else start();
})();
