// A lesson page's script: the URL's state becomes the lesson's command line, the lesson's program
// (NN-name.js, built by Emscripten from the lesson's C++) runs on the canvas, and the controls are
// made from the lesson's own declarations (LessonInfo), which the program hands over when ready.
//
// The URL: ?variant=V&time=T&size=WxH&set=NAME:VALUE,NAME:VALUE&paused=1&view=stencil&pass=3
// &orbit=AZIMUTH,ELEVATION,DISTANCE&scene=csg/drilled-box.scene (&without=EXT,EXT: below)
// (view: colour, stencil, grey, bits or depth; pass: the frame as it was after that pass, 1 the first;
// orbit: the camera in degrees and world units; scene: one of the scene files the scene lessons
// offer, tests/scenes/ in the repository. A scene file dropped on the page is not in the URL.)
// The snapshot contract (the tests'): with &snapshot=1 the frame at that time and size is drawn,
// then <img id="snapshot-colour"> and <img id="snapshot-stencil"> (PNG data URLs; the stencil one
// grey byte a pixel, as --stencil-out's .raw.png) are added to the page and document.title is
// "snapshot-ready", or "snapshot-error: MESSAGE" when the frame cannot be drawn.
'use strict';

const lessonId = document.body.dataset.lesson;
const params = new URLSearchParams(location.search);
const snapshot = params.get('snapshot') === '1';
const statusLine = document.getElementById('status');
const logBox = document.getElementById('log');
let lesson = null;  // the lesson's declarations, once its program is ready
let failed = false;
let refusedAt = -Infinity;  // performance.now() of the last refusal
let passLabels = [];  // the passes the last frame ran
let frameTime = 0;  // the last frame's time, seconds
// A number for the URL that gives the same frame back: 9 significant digits hold a float exactly.
const exactly = value => String(Number(value.toPrecision(9)));
const views = ['colour', 'stencil', 'grey', 'bits', 'depth'];
const maxLegendEntries = 48;

function log(text) {
  console.log(text);
  logBox.textContent += text + '\n';
}

// The lesson's command line from the URL; what is not a setting of the URL is left out.
function commandLine() {
  const args = [];
  if (params.has('variant')) args.push('--variant', params.get('variant'));
  if (params.has('time')) args.push('--time', params.get('time'));
  if (params.has('size')) args.push('--size', params.get('size'));
  if (params.has('set'))
    for (const setting of params.get('set').split(',').filter(s => s))
      args.push('--set', setting.replace(':', '='));
  // One of the offered files, by its name under /scenes; anything else is the program's to refuse.
  if (params.has('scene')) args.push('--scene', '/scenes/' + params.get('scene').replace(/^\/+/, ''));
  return args;
}

// Keeps the URL the state the page shows, so that a link restores it.
function updateUrl(changes) {
  for (const [key, value] of Object.entries(changes)) {
    if (value === null || value === undefined || value === '') params.delete(key);
    else params.set(key, value);
  }
  // ':', ',' and '/' read as themselves in a query: the link stays readable.
  const query = params.toString().replace(/%3A/gi, ':').replace(/%2C/gi, ',').replace(/%2F/gi, '/');
  history.replaceState(null, '', query ? '?' + query : location.pathname);
}

function base64(bytes) {
  let text = '';
  for (let i = 0; i < bytes.length; i += 0x8000)
    text += String.fromCharCode.apply(null, bytes.subarray(i, i + 0x8000));
  return btoa(text);
}

// Called by the lesson's program (common/gl/web_run.cpp).
window.StencilPage = {
  error(message) {
    failed = true;
    statusLine.textContent = message;
    statusLine.className = 'error';
    log('error: ' + message);
    if (snapshot) document.title = 'snapshot-error: ' + message;
  },
  // What the reader asked for could not be done (a scene file that cannot be read); the lesson
  // keeps running as it was.
  refused(message) {
    message = inPagesWords(message);
    // Refusals of one load (a URL with two bad values) are all said.
    if (statusLine.className === 'error' && performance.now() - refusedAt < 1000)
      message = statusLine.textContent + '; ' + message;
    statusLine.textContent = message;
    statusLine.className = 'error';
    refusedAt = performance.now();
    log('refused: ' + message);
    if (snapshot) {
      failed = true;
      document.title = 'snapshot-error: ' + message;
    }
  },
  // The view's legend below the picture: a line, and for the stencil's ramp and grey views each value
  // present as [value, pixels, "#rrggbb"] (the window draws the same in a band under the picture).
  legend(legend) {
    const box = document.getElementById('legend');
    box.textContent = '';
    if (!legend.rule) return;
    box.append(legend.rule + (legend.entries ? ':' : ''));
    // A frame whose last passes clear the depth (lesson 13 draws its count over the whole picture)
    // shows none: the passes before show what they left.
    if (legend.rule.startsWith('depth: nothing drawn') && currentPass === 0)
      box.append(' (at the frame\'s end; the pass stepper shows the depth each pass left)');
    const entries = legend.entries || [];
    for (const [value, pixels, colour] of entries.slice(0, maxLegendEntries)) {
      const entry = document.createElement('span');
      entry.className = 'entry';
      const swatch = document.createElement('span');
      swatch.className = 'swatch';
      swatch.style.background = colour;
      entry.append(swatch, value + ' (' + pixels + ' px)');
      box.append(' ', entry);
    }
    if (entries.length > maxLegendEntries) box.append(' +' + (entries.length - maxLegendEntries) + ' more values');
  },
  image(id, bytes) {
    const img = document.createElement('img');
    img.id = id;
    img.alt = id;
    img.src = 'data:image/png;base64,' + base64(bytes);
    document.getElementById('live').appendChild(img);
  },
  ready(info) {
    const first = lesson === null;
    lesson = info;  // the program has logged its renderer and features
    if (first && info.urlRefused) {  // the URL keeps what the lesson draws instead
      const scene = info.scene.startsWith('/scenes/') ? info.scene.slice('/scenes/'.length) : null;
      const drawn = (key, value) => params.has(key) ? value : null;
      updateUrl({variant: drawn('variant', info.variant), set: info.changed.join(',') || null,
                 time: drawn('time', exactly(info.time)), size: drawn('size', info.size.join('x')), scene});
    }
    if (first) applyUrlOrbit();
    if (snapshot) return;
    makeControls(info);
    if (first) setUpOrbit();
  },
  frame(time, passes) {
    if (failed) return;
    passLabels = passes;
    frameTime = time;
    // A refusal stays in view for 6 s before the frame's line takes its place again.
    if (performance.now() - refusedAt > 6000) {
      statusLine.className = '';
      statusLine.textContent = 't = ' + time.toFixed(2) + ' s; passes: ' + passes.join(', ');
    }
    showPass();
    const timeBox = document.getElementById('time');
    if (timeBox && document.activeElement !== timeBox) timeBox.value = time.toFixed(2);
  },
};

// The command line's words for the URL's and the controls' (a refusal's message is the command line's).
function inPagesWords(message) {
  return message.replace(/--list-variants shows them/, 'the variant list shows them')
      .replace(/--help lists the options/, 'the controls list the options')
      .replace(/^--(variant|time|size|set|scene)\b/, '$1')
      .replace(/ --set (\w+)=/g, ' $1 ').replace(/ --scene /g, ' the scene file ')
      .replace(/\/dropped\/\d+\/scene\/|\/scenes\//g, '');  // the file's name, not where the page put it
}

// The URL's set=: the options away from the values their variant gives them (the others follow
// the variant when the URL is loaded), null when none is.
function settingsOf(info) {
  return info.options.filter(o => o.value !== o.variantValue).map(o => o.name + ':' + o.value).join(',') || null;
}

function makeControls(info) {
  const box = document.getElementById('controls');
  box.textContent = '';
  const label = (text, element, title, parent = box) => {
    const l = document.createElement('label');
    l.textContent = text;
    if (title) l.title = title.replace(/\s+/g, ' ');  // the help's line breaks are the terminal's
    l.appendChild(element);
    parent.appendChild(l);
    return element;
  };
  const variant = document.createElement('select');
  variant.id = 'variant';
  for (const v of info.variants) {
    const option = document.createElement('option');
    option.value = v.name;
    option.textContent = v.name;
    option.title = v.help.replace(/\s+/g, ' ');
    option.selected = v.name === info.variant;
    variant.appendChild(option);
  }
  // A variant sets every option anew: the page loads again with it in the URL, so that the
  // controls show the variant's values.
  variant.addEventListener('change', () => {
    updateUrl({variant: variant.value, set: null, pass: null});
    location.search = '?' + params.toString();
  });
  label('variant', variant, info.variants.find(v => v.name === info.variant)?.help);
  const variantHelp = document.createElement('span');  // what the variant shows, in view (a title is not, on a touch screen)
  variantHelp.className = 'help';
  variantHelp.textContent = (info.variants.find(v => v.name === info.variant)?.help ?? '') +
                            (info.scene ? ' (drawn with the scene file ' + info.scene.replace(/^\/scenes\//, '') + ')' : '');
  box.appendChild(variantHelp);
  const time = document.createElement('input');
  time.id = 'time';
  time.type = 'number';
  time.step = '0.1';
  time.value = info.time.toFixed(2);
  time.addEventListener('change', () => {
    const seconds = Number(time.value);
    if (time.value.trim() === '' || !Number.isFinite(seconds)) {
      // As the URL's time is refused; a number box empties what is not a number (badInput).
      StencilPage.refused('time expects a number of seconds, got ' +
                          (time.validity.badInput ? 'something else' : 'nothing'));
      time.value = frameTime.toFixed(2);
      return;
    }
    refusedAt = -Infinity;
    Module._stencil_web_time(seconds);
    updateUrl({time: time.value});
  });
  label('time (s)', time);
  const view = document.createElement('select');
  view.id = 'view';
  for (const name of views) {
    const option = document.createElement('option');
    option.value = name;
    option.textContent = name;
    view.appendChild(option);
  }
  view.addEventListener('change', () => {
    if (Module._stencil_web_view(views.indexOf(view.value)) === 0)
      updateUrl({view: view.value === 'colour' ? null : view.value});
  });
  label('view', view);
  if (info.readsScenes) makeSceneControls(info, label);
  // The pass stepper: the frame as it was after each pass that ran, forward and back.
  const stepper = document.createElement('span');
  stepper.id = 'stepper';
  const back = document.createElement('button'), forward = document.createElement('button');
  back.id = 'pass-back';
  forward.id = 'pass-forward';
  back.textContent = '\u25c0';
  forward.textContent = '\u25b6';
  const passName = document.createElement('span');
  passName.id = 'pass-name';
  stepper.append(back, ' ', passName, ' ', forward);
  const step = delta => {
    const count = passLabels.length;
    // 0 the whole frame; 1..count after that pass
    currentPass = ((currentPass + delta) % (count + 1) + count + 1) % (count + 1);
    if (currentPass > 0) setPlaying(false);
    Module._stencil_web_pass(currentPass - 1);
    updateUrl({pass: currentPass || null});
    showPass();
  };
  back.addEventListener('click', () => step(-1));
  forward.addEventListener('click', () => step(1));
  label('pass ', stepper);
  const play = document.createElement('button');
  play.id = 'play';
  let playing = params.get('paused') !== '1';
  const setPlaying = on => {
    playing = on;
    play.textContent = on ? 'pause' : 'play';
    Module._stencil_web_play(on ? 1 : 0);
    updateUrl({paused: on ? null : '1'});
    if (!on) updateUrl({time: exactly(frameTime)});  // the frame shown, not the box's 2 decimals
  };
  play.addEventListener('click', () => setPlaying(!playing));
  box.appendChild(play);
  // The lesson's options after the controls every lesson has, so that those stay near the picture.
  const options = document.createElement('div');
  options.id = 'options';
  box.appendChild(options);
  for (const o of info.options) {
    const input = document.createElement('input');
    input.id = 'option-' + o.name;
    if (o.min === 0 && o.max === 1) {
      input.type = 'checkbox';
      input.checked = o.value !== 0;
    } else {
      input.type = 'number';
      input.min = o.min;
      input.max = o.max;
      input.value = o.value;
    }
    input.addEventListener('change', () => {
      const value = input.type === 'checkbox' ? (input.checked ? 1 : 0) : Number(input.value);
      refusedAt = -Infinity;  // the frame's line again, unless this one is refused too
      if (!Number.isInteger(value)) {
        StencilPage.refused('option \'' + o.name + '\' takes whole numbers ' + o.min + '..' + o.max + ', got ' + input.value);
        input.value = o.value;
        return;
      }
      if (Module.ccall('stencil_web_option', 'number', ['string', 'number'], [o.name, value]) !== 0) {
        if (input.type === 'checkbox') input.checked = o.value !== 0;  // refused: the box shows what is drawn
        else input.value = o.value;
        return;
      }
      o.value = value;
      updateUrl({set: settingsOf(info)});
    });
    label(o.name, input, o.help, options);
  }
  // The URL's view and pass; one it cannot show is said, and left out of the URL.
  if (params.has('view') && !views.includes(params.get('view'))) {
    StencilPage.refused('view=' + params.get('view') + ': expected ' + views.join(', '));
    updateUrl({view: null});
  } else if (params.has('view')) {
    view.value = params.get('view');
    Module._stencil_web_view(views.indexOf(view.value));
  }
  const passParam = Number(params.get('pass') || 0);
  if (!Number.isInteger(passParam) || passParam < 0 || passParam > passLabels.length) {
    StencilPage.refused('pass=' + params.get('pass') + ': expected 1 to ' + passLabels.length +
                        ', a pass of the ' + passLabels.length + ' this frame ran');
    updateUrl({pass: null});
  } else if (passParam > 0) {
    currentPass = passParam;
    playing = false;
    Module._stencil_web_pass(currentPass - 1);
  }
  setPlaying(playing);
  showPass();
}

// The scene lessons' scene: one of the files they offer, or a scene file (with its OBJ meshes)
// picked or dropped on the canvas.
function makeSceneControls(info, label) {
  const scene = document.createElement('select');
  scene.id = 'scene';
  const current = info.scene.startsWith('/scenes/') ? info.scene.slice('/scenes/'.length) : info.scene;
  const names = ['', ...info.scenes];
  if (current && !info.scenes.includes(current)) names.push(current);
  for (const name of names) {
    const option = document.createElement('option');
    option.value = name;
    option.textContent = name === '' ? "(the lesson's own)" : name.startsWith('/dropped/') ? name.split('/').pop() : name;
    option.selected = name === current;
    scene.appendChild(option);
  }
  let drawn = scene.value;
  scene.addEventListener('change', () => {
    if (scene.value.startsWith('/dropped/')) return;
    refusedAt = -Infinity;  // the frame's line again, unless this one is refused too
    if (Module.ccall('stencil_web_scene', 'number', ['string'], [scene.value && '/scenes/' + scene.value]) === 0) {
      drawn = scene.value;
      updateUrl({scene: scene.value || null, orbit: null});
    } else {
      scene.value = drawn;  // refused: the list names the scene still drawn
    }
  });
  label('scene file', scene, 'a scene file of tests/scenes/, or drop a .scene file and its .obj meshes on the picture');
  const pick = document.createElement('input');
  pick.id = 'scene-file';
  pick.type = 'file';
  pick.multiple = true;
  pick.accept = '.scene,.obj';
  pick.addEventListener('change', () => loadSceneFiles(pick.files));
  label('your scene file', pick, 'a .scene file and the .obj meshes it names');
}

const maxSceneFileBytes = 64 * 1024 * 1024;
let droppedCount = 0;

// Writes the picked or dropped files into the program's files and loads the scene file among them:
// each .obj beside the scene file, and again where the scene's `mesh PATH` names a file of that name
// (relative to the scene file, as the scene format reads it), so that a scene naming meshes/x.obj
// finds the x.obj dropped with it. What cannot be loaded is one line on the page; the lesson keeps
// its scene.
async function loadSceneFiles(fileList) {
  const files = Array.from(fileList);
  if (!lesson || !lesson.readsScenes) return StencilPage.refused(lessonId + ' draws only its own scene; the scene lessons read scene files');
  const other = files.find(f => !/\.(scene|obj)$/i.test(f.name));
  if (other) return StencilPage.refused(other.name + ': not a scene file (.scene) or an OBJ mesh (.obj)');
  const scenes = files.filter(f => /\.scene$/i.test(f.name));
  if (scenes.length !== 1)
    return StencilPage.refused(scenes.length ? scenes.length + ' scene files: drop one at a time, with its .obj meshes'
                                             : 'no scene file (.scene) among the files: drop one with its .obj meshes');
  const large = files.find(f => f.size > maxSceneFileBytes);
  if (large) return StencilPage.refused(large.name + ': ' + (large.size / 1048576).toFixed(0) + ' MiB, more than the page reads (64 MiB)');
  const folder = '/dropped/' + ++droppedCount + '/scene';
  const FS = Module.FS;
  FS.mkdirTree(folder);
  const sceneBytes = new Uint8Array(await scenes[0].arrayBuffer());
  FS.writeFile(folder + '/' + scenes[0].name, sceneBytes);
  const meshPaths = [...new TextDecoder().decode(sceneBytes).matchAll(/(?:^|\s)mesh\s+(\S+)/gm)].map(m => m[1]);
  for (const mesh of files.filter(f => /\.obj$/i.test(f.name))) {
    const bytes = new Uint8Array(await mesh.arrayBuffer());
    const places = [mesh.name, ...meshPaths.filter(p => !p.startsWith('/') && p.split('/').pop() === mesh.name)];
    for (const place of places) {
      const path = normalise(folder + '/' + place);
      FS.mkdirTree(path.slice(0, path.lastIndexOf('/')));
      FS.writeFile(path, bytes);
    }
  }
  const path = folder + '/' + scenes[0].name;
  refusedAt = -Infinity;
  if (Module.ccall('stencil_web_scene', 'number', ['string'], [path]) === 0) {
    updateUrl({scene: null, orbit: null});
    log('scene: ' + scenes[0].name + ' (' + files.length + (files.length === 1 ? ' file' : ' files') + '), not in the URL');
  }
}

// A path with its '.' and '..' steps taken (never above the root).
function normalise(path) {
  const parts = [];
  for (const part of path.split('/')) {
    if (part === '..') parts.pop();
    else if (part && part !== '.') parts.push(part);
  }
  return '/' + parts.join('/');
}

// Orbit and zoom as in the window: a drag on the picture turns the camera 0.4 degrees a pixel, the
// wheel moves it 10% nearer or farther a notch. The URL keeps the camera (&orbit=) once it stops.
function orbitValue() {
  return [0, 1, 2].map(i => Module._stencil_web_orbit_value(i));
}
function keepOrbitInUrl() {
  updateUrl({orbit: orbitValue().map(exactly).join(',')});
}
function setUpOrbit() {
  const canvas = document.getElementById('canvas');
  let drag = null;
  canvas.addEventListener('pointerdown', e => {
    if (e.button !== 0) return;
    drag = {x: e.clientX, y: e.clientY};
    canvas.setPointerCapture(e.pointerId);
  });
  canvas.addEventListener('pointermove', e => {
    if (!drag) return;
    Module._stencil_web_orbit(-(e.clientX - drag.x) * 0.4, (e.clientY - drag.y) * 0.4, 1);
    drag = {x: e.clientX, y: e.clientY};
  });
  const end = () => {
    if (!drag) return;
    drag = null;
    keepOrbitInUrl();
  };
  canvas.addEventListener('pointerup', end);
  canvas.addEventListener('pointercancel', end);
  let wheelTimer = 0;
  canvas.addEventListener('wheel', e => {
    e.preventDefault();
    Module._stencil_web_orbit(0, 0, Math.pow(0.9, -Math.sign(e.deltaY)));
    clearTimeout(wheelTimer);
    wheelTimer = setTimeout(keepOrbitInUrl, 300);
  }, {passive: false});
  canvas.addEventListener('dragover', e => e.preventDefault());
  canvas.addEventListener('drop', e => {
    e.preventDefault();
    loadSceneFiles(e.dataTransfer.files);
  });
}

// The URL's camera (&orbit=AZIMUTH,ELEVATION,DISTANCE), as turns and a zoom from where it stands.
function applyUrlOrbit() {
  if (!params.has('orbit')) return;
  const wanted = params.get('orbit').split(',').map(Number);
  if (wanted.length !== 3 || !wanted.every(Number.isFinite) || wanted[2] <= 0) {
    StencilPage.refused('orbit=' + params.get('orbit') + ': expected AZIMUTH,ELEVATION,DISTANCE (degrees, degrees, world units > 0)');
    return updateUrl({orbit: null});
  }
  const [azimuth, elevation, distance] = orbitValue();
  Module._stencil_web_orbit(wanted[0] - azimuth, wanted[1] - elevation, wanted[2] / distance);
}

let currentPass = 0;  // 0: the whole frame; N: as it was after the N-th pass that ran
function showPass() {
  const name = document.getElementById('pass-name');
  if (!name) return;
  name.textContent = currentPass === 0 ? 'whole frame (' + passLabels.length + ' passes)'
      : currentPass + ' of ' + passLabels.length + ': ' + (passLabels[currentPass - 1] ?? '(not run in this frame)');
}

window.Module = {
  canvas: document.getElementById('canvas'),
  arguments: commandLine(),
  print: log,
  printErr: log,
  postRun: [() => {
    if (!snapshot) return;
    if (failed || !lesson) {
      if (!failed) StencilPage.error('the lesson did not start');
      return;
    }
    if (Module._stencil_web_snapshot() === 0) document.title = 'snapshot-ready';
  }],
  onAbort: what => StencilPage.error('the lesson stopped: ' + what),
};
window.addEventListener('error', e => StencilPage.error(e.message));

// &without=EXT,EXT hides those WebGL extensions from the lesson, to show (and test) the fallback a
// browser without them takes; the page's log says which features the lesson found.
const hidden = (params.get('without') || '').split(',').filter(name => name);
if (hidden.length) {
  const context = WebGL2RenderingContext.prototype;
  const getExtension = context.getExtension, supported = context.getSupportedExtensions;
  context.getExtension = function(name) { return hidden.includes(name) ? null : getExtension.call(this, name); };
  context.getSupportedExtensions = function() { return supported.call(this).filter(n => !hidden.includes(n)); };
  log('extensions hidden by the URL: ' + hidden.join(', '));
}

const program = document.createElement('script');
program.src = lessonId + '.js';
document.body.appendChild(program);
