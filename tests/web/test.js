// SPDX-License-Identifier: MIT
// The browser side of the image tests (tests/web/run.sh): for each case
// (?scene=NAME&size=WxH&cases=a,b), a stin context with the case's shadow
// technique, and per output (beauty with its depth, normal, visibility of
// light 0) the offscreen read-back posted as RESULT/SCENE-CASE-OUTPUT.rgba,
// with SCENE-CASE.txt: the frames' status, stin's choice, log and projection.
'use strict';

// sweep: every scene with stin's own choice at its best tier, on a small
// front end of its own (?sweep=WxH, default 128x96), frames not read back:
// drawn, or the fall-back stin names. The other cases force tier gl2 (or the one they name) and
// their technique: force: techniques by name; options: web_option's;
// scenes: the scenes a case is for; variant: a view of the scene packed of its
// own. browser_test.c's table agrees.
const CASES = {
  sweep: { tier: 'auto', shadows: '', sweep: true },
  lighting: { shadows: 'shadows-off', size: 0, kernel: 0, scenes: ['four-lights'] },
  volume: { shadows: 'volume', size: 0, kernel: 0, scenes: ['four-lights'] },
  'map-pcf-1024-k3': { shadows: 'map-pcf', size: 1024, kernel: 3, scenes: ['four-lights'] },
  // coloured_test.c's options: deep's 512 a side on glass-panes, shadows stin's
  coloured: { shadows: '', force: ['coloured'], options: { deep_map_size: 512 }, scenes: ['glass-panes'] },
  // tier gl4, WebGL 2's default: deep_test.c's options on glass-panes (512 a face, six layers)
  deep: { tier: 'gl4', shadows: '', force: ['deep'], options: { deep_map_size: 512, deep_layers: 6 }, scenes: ['glass-panes'] },
  'lighting-gl4': { tier: 'gl4', shadows: 'shadows-off', size: 0, kernel: 0, scenes: ['four-lights'] },
  'volume-gl4': { tier: 'gl4', shadows: 'volume', size: 0, kernel: 0, scenes: ['four-lights'] },
  'pom-gl4': { tier: 'gl4', shadows: 'shadows-off', force: ['pom'], scenes: ['stone-wall'] },
  'depth-peel': { shadows: 'shadows-off', force: ['depth-peel'], scenes: ['glass-panes'] },
  normal: { shadows: 'shadows-off', force: ['normal'], scenes: ['stone-wall'] },
  pom: { shadows: 'shadows-off', force: ['pom'], scenes: ['stone-wall'] },
  // surface_test.c's views of stone-wall (variant: its pack scenes/variants/SCENE.VARIANT):
  // parallax and normal mapping seen straight down; parallax's uv shift through a uv gradient
  'parallax-down': { shadows: 'shadows-off', force: ['parallax'], variant: 'parallax-down', scenes: ['stone-wall'] },
  'parallax-down-normal': { shadows: 'shadows-off', force: ['normal'], variant: 'parallax-down', scenes: ['stone-wall'] },
  'parallax-limit': { shadows: 'shadows-off', force: ['parallax'], variant: 'parallax-limit', scenes: ['stone-wall'] },
  displace: { shadows: 'shadows-off', force: ['displace'], scenes: ['displace-plate'] },
  // techniques WebGL 2 cannot run: forced at stin's best tier, frames not read
  // back; stin must fall back and say why (a SKIP row with its reason)
  'skip-dual-peel': { tier: 'auto', shadows: 'shadows-off', force: ['dual-peel'], skip: true, scenes: ['glass-panes'] },
  'skip-vdsm': { tier: 'auto', shadows: 'vdsm', skip: true, scenes: ['four-lights'] },
  'skip-displace-tess': { tier: 'auto', shadows: 'shadows-off', force: ['displace-tess'], skip: true, scenes: ['displace-tess'] },
  'skip-interval': { tier: 'auto', shadows: 'shadows-off', force: ['interval'], options: { csg_product: 0 }, skip: true, scenes: ['csg'] },
  // a browser without WebGL 2 (refused 'webgl2' contexts): the front end must refuse
  webgl1: { refusal: true, scenes: ['four-lights'] },
  // csg.json's csg list: carved, both, common; one product at a time, as csg_test.c draws them
  'scs-carved': { shadows: 'shadows-off', force: ['scs'], options: { csg_product: 0 }, scenes: ['csg'] },
  'scs-both': { shadows: 'shadows-off', force: ['scs'], options: { csg_product: 1 }, scenes: ['csg'] },
  'scs-common': { shadows: 'shadows-off', force: ['scs'], options: { csg_product: 2 }, scenes: ['csg'] },
  'goldfeather-carved': { shadows: 'shadows-off', force: ['goldfeather'], options: { csg_product: 0 }, scenes: ['csg'] },
  'goldfeather-both': { shadows: 'shadows-off', force: ['goldfeather'], options: { csg_product: 1 }, scenes: ['csg'] },
  'goldfeather-common': { shadows: 'shadows-off', force: ['goldfeather'], options: { csg_product: 2 }, scenes: ['csg'] },
};

async function post(where, data) {
  await fetch(where, { method: 'POST', body: data });
}

// The refusal case: a canvas of its own whose 'webgl2' contexts are refused
// (WebGL 1 stays), as in a browser without WebGL 2; the front end's answer
// (init 0 and its message, shown on the page) posted as SCENE-webgl1.txt.
async function refusal(scene) {
  const canvas = document.createElement('canvas');
  const get = HTMLCanvasElement.prototype.getContext;
  const meta = [];
  canvas.id = 'webgl1';
  document.body.appendChild(canvas);
  HTMLCanvasElement.prototype.getContext = function (kind, ...rest) {
    return /webgl2/.test(kind) ? null : get.call(this, kind, ...rest);
  };
  try {
    await stinFront('#webgl1', 64, 48);
    meta.push('init 1');
  } catch (e) {
    meta.push('init 0', 'message ' + e.message);
    document.getElementById('message').textContent = e.message;
  } finally {
    HTMLCanvasElement.prototype.getContext = get;
  }
  await post(`/result/${scene}-webgl1.txt`, meta.join('\n') + '\n');
}

// One case's context and frames (beauty with its depth, normal, visibility),
// read back and posted where readBack, and SCENE-NAME.txt.
async function draw(f, scene, name, c, readBack) {
  const meta = [];
  await post('/log', `browser: ${scene} ${name}`);
  f.force('');
  for (const t of c.force || []) f.force(t);
  for (const [k, v] of Object.entries(c.options || {})) f.option(k, v);
  if (!f.create(c.tier || 'gl2', c.shadows, c.size || 0, c.kernel || 0)) {
    meta.push('created 0');
  } else {
    meta.push('created 1');
    const outputs = [['beauty', 0], ['normal', 1], ['vis', 2]];
    for (const [label, output] of outputs) {
      await post('/log', `browser: ${scene} ${name} ${label} frame`);
      const ok = f.frame(output, 1);
      meta.push(`status ${label} ${f.frameStatus()}`);
      meta.push(`frame ${label} ${ok}`);
      if (!readBack) continue;
      await post(`/result/${scene}-${name}-${label}.rgba`, f.read(0));
      if (output === 0) {
        meta.push('projection ' + f.projection().join(' '));
        await post(`/result/${scene}-${name}-depth.rgba`, f.read(1));
      }
    }
  }
  meta.push('log_errors ' + f.logErrors());
  for (const line of f.choice().split('\n')) if (line) meta.push('choice ' + line);
  for (const line of f.log().split('\n')) if (line) meta.push('log ' + line);
  await post(`/result/${scene}-${name}.txt`, meta.join('\n') + '\n');
}

// The sweep's front end, made at its first scene.
let sweepFront = null;

async function sweep(scene, size) {
  if (!sweepFront) {
    const canvas = document.createElement('canvas');
    canvas.id = 'sweep';
    document.body.appendChild(canvas);
    sweepFront = await stinFront('#sweep', size[0], size[1]);
  }
  await sweepFront.loadScene(`scenes/${scene}.stinscene`);
  await draw(sweepFront, scene, 'sweep', CASES.sweep, false);
}

(async () => {
  const q = new URLSearchParams(location.search);
  const [w, h] = (q.get('size') || '256x192').split('x').map(Number);
  const small = (q.get('sweep') || '128x96').split('x').map(Number);
  const names = (q.get('cases') || 'lighting').split(',').filter((n) => CASES[n]);
  try {
    const f = await stinFront('#view', w, h);
    const gl = document.createElement('canvas').getContext('webgl2');
    await post('/log', 'browser: ' + (gl ? gl.getParameter(gl.VERSION) : 'no WebGL 2'));
    for (const scene of (q.get('scenes') || 'four-lights').split(',')) {
      const mine = names.filter((n) => !CASES[n].scenes || CASES[n].scenes.includes(scene));
      let loaded = null; // the pack in f: a case's variant loads its own
      for (const name of mine) {
        const c = CASES[name];
        const pack = c.variant ? `scenes/variants/${scene}.${c.variant}` : `scenes/${scene}`;
        if (!c.sweep && !c.refusal && loaded !== pack) await f.loadScene(`${pack}.stinscene`);
        if (!c.sweep && !c.refusal) loaded = pack;
        if (c.refusal) await refusal(scene);
        else if (c.sweep) await sweep(scene, small);
        else await draw(f, scene, name, c, !c.skip);
      }
    }
  } catch (e) {
    await post('/log', 'browser: ' + e);
  }
  await post('/done', '');
})();
