// SPDX-License-Identifier: MIT
// The demo page: a scene pack of the repository drawn by stin into the
// canvas; drag to orbit, wheel to move closer; the pickers make a new stin
// context, whose choice and log are shown. ?scene=NAME picks the first scene.
'use strict';

(async () => {
  const $ = (id) => document.getElementById(id);
  const canvas = $('view');
  let f;
  try {
    f = await stinFront('#view', canvas.width, canvas.height);
  } catch (e) { // no WebGL 2: the reason on the page, nothing drawn
    $('choice').textContent = 'stin does not run here: ' + e.message;
    return;
  }
  const view = { yaw: 0, pitch: 0, scale: 1 };
  let pending = false;

  // the log, and its warnings as the fall-backs (some are logged at the first frame)
  function showLog() {
    const log = f.log();
    const warnings = log.split('\n').filter((l) => l.startsWith('warning: '));
    $('log').textContent = log;
    $('fallbacks').textContent = warnings.length ? warnings.join('\n') : 'none';
  }
  function draw() {
    pending = false;
    f.orbit(view.yaw, view.pitch, view.scale);
    const ok = f.frame(Number($('output').value), 0);
    // (a headless screenshot's virtual clock stands still: no time to show)
    const ms = f.frameMs();
    $('time').textContent = !ok ? 'frame failed: ' + f.frameStatus() : ms > 0 ? `frame ${ms.toFixed(1)} ms` : '';
    showLog();
  }
  function redraw() {
    if (!pending) {
      pending = true;
      requestAnimationFrame(draw);
    }
  }
  function context() {
    const ok = f.create($('tier').value, $('shadows').value, 0, 0);
    $('choice').textContent = ok ? f.choice() : 'no stin context: ' + $('tier').value +
      ' with ' + ($('shadows').value || 'auto') + ' shadows is refused here (see the log)';
    showLog();
    if (ok) redraw();
    else $('time').textContent = '';
  }
  async function scene() {
    await f.loadScene(`scenes/${$('scene').value}.stinscene`);
    Object.assign(view, { yaw: 0, pitch: 0, scale: 1 });
    context();
  }

  const names = (await (await fetch('scenes/list.txt')).text()).split('\n').filter(Boolean);
  for (const n of names) $('scene').add(new Option(n, n));
  $('scene').value = new URLSearchParams(location.search).get('scene') || 'four-lights';
  $('scene').onchange = scene;
  $('tier').onchange = context;
  $('shadows').onchange = context;
  $('output').onchange = redraw;

  let drag = null;
  canvas.onpointerdown = (e) => { drag = [e.clientX, e.clientY]; canvas.setPointerCapture(e.pointerId); };
  canvas.onpointerup = () => { drag = null; };
  canvas.onpointermove = (e) => {
    if (!drag) return;
    view.yaw -= (e.clientX - drag[0]) * 0.4;
    view.pitch += (e.clientY - drag[1]) * 0.3;
    drag = [e.clientX, e.clientY];
    redraw();
  };
  canvas.onwheel = (e) => {
    e.preventDefault();
    view.scale = Math.min(4, Math.max(0.2, view.scale * (e.deltaY > 0 ? 1.1 : 0.9)));
    redraw();
  };
  await scene();
})();
