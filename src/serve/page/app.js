// tippe serve's page: a form made from the design, and the zones, the plot, a
// launch, a film and the build zip drawn from the API's JSON (docs/serve.md).
// Plain JavaScript, no library: it works offline.
'use strict';

const $ = (id) => document.getElementById(id);
const SVG = 'http://www.w3.org/2000/svg';
const token = new URLSearchParams(location.search).get('token');
const GROUP_COLOR = { I: '#3f8f4f', Ia: '#3f8f4f', Ib: '#3f8f4f', IIa: '#d9a51b', IIb: '#e07b24',
                      IIc: '#c4541c', III: '#a23a8f' };
const GROUP_MEANING = { I: 'stays up', IIa: 'flips (II)', IIb: 'flips (II)', IIc: 'flips (II)',
                        III: 'hangs' };

// One line for each term the page uses (hover; docs/serve.md, "Terms", has the same words).
const TERMS = {
  'A/C': 'A/C: the top\'s moment of inertia about a horizontal axis through its centre of mass over the one about its symmetry axis (paper, section 2)',
  'eps/R': 'eps/R: how far the centre of mass lies from the sphere\'s centre (eps), over the sphere\'s radius R; its sign says which side is down',
  'robust': 'robust: the part of a zone left when the tolerance bands of both its ends are taken off: where the weight can be set whatever the print and the parts do within their tolerances',
  'band': 'band: how far a zone\'s boundary moves when every tolerance of the design (printed sizes, densities, infill) moves by its stated amount, combined in quadrature',
  'trapped': 'trapped: the launch\'s energy is below the barrier of the well it is in, so it stays in that well for ever: the verdict is proved, not observed',
  'patch law': 'patch law: Coulomb friction on a small spinning contact patch (Contensou), whose drilling couple changes Jellett\'s J: its verdicts are observed at the end of the run, not proved',
  'narrowest': 'narrowest zone: the narrowest of the widest runs of stays up (I), flips (II) and hangs (III) within the travel where the model applies; runs of one group on either side of eps/R = 0 are counted together',
};
// A term with its one-line explanation on hover (and on focus, for the keyboard).
function term(word, shown) {
  const a = document.createElement('abbr');
  a.className = 'term'; a.title = TERMS[word]; a.textContent = shown || word; a.tabIndex = 0;
  return a;
}

const state = {
  design: null,       // the design as edited (a design file's JSON)
  name: '',           // the shipped design it came from, if any
  sweep: null,        // the last valid sweep
  verdict: null,      // the build sheet's verdict of that sweep's design (/api/verdict)
  advice: null,       // its launch checks and the changes one can buy (/api/advice)
  vseq: 0,            // the latest valid sweep: a verdict for an older one is dropped
  adviceAbort: null,  // cancels the advice asked for an older design
  pinned: null,       // {design, sweep, title}
  materials: [],
  seq: 0,             // the latest request sent: older answers are dropped
  z2: null,
  lseq: 0,            // the launch's inputs: a check of older ones is dropped
  original: null,     // the design as opened (JSON text): a field's reset, "edited"
  source: 'shipped',  // where it came from: 'shipped', 'file' (state.name its stem), 'pasted'
  undo: [],           // earlier versions (JSON texts), the latest last
  lastEdit: { path: null, t: 0 },
  sweepDesign: null,  // the design (a copy) state.sweep is of
  shownTitle: '',     // whose results are on screen
  pinWanted: false,   // "Pin" pressed while a sweep ran: pin that design with its sweep
  gcodeNames: {},     // "upload:ID" -> the uploaded file's name and slicer
  gcodeFiles: {},     // "upload:ID" -> the uploaded file's name (Save JSON names it)
  catalogue: [],      // the designs folder's screws (GET /api/catalogue)
};

// ------------------------------------------------------------------ API

async function api(path, body, signal) {
  const headers = { 'Content-Type': 'application/json' };
  if (token) headers['X-Tippe-Token'] = token;
  const init = body === undefined ? { headers } : { method: 'POST', headers, body: JSON.stringify(body) };
  if (signal) init.signal = signal;
  const r = await fetch(path, init);
  const type = r.headers.get('Content-Type') || '';
  if (type.startsWith('application/json')) return { ok: r.ok, status: r.status, json: await r.json() };
  return { ok: r.ok, status: r.status, blob: await r.blob(), type };
}

// ------------------------------------------------------------------ SVG helpers

function el(name, attrs, parent, text) {
  const e = document.createElementNS(SVG, name);
  for (const k in attrs) e.setAttribute(k, attrs[k]);
  if (text !== undefined) e.textContent = text;
  if (parent) parent.appendChild(e);
  return e;
}

let tip = null;
function showTip(ev, text) {
  if (!tip) { tip = document.createElement('div'); tip.className = 'tip'; document.body.appendChild(tip); }
  tip.textContent = text;
  tip.style.left = (ev.clientX + 12) + 'px';
  tip.style.top = (ev.clientY + 12) + 'px';
  tip.hidden = false;
}
function hideTip() { if (tip) tip.hidden = true; }

const fmt = (x, d = 2) => (x === null || x === undefined || !isFinite(x)) ? '—' : Number(x).toFixed(d);

// ------------------------------------------------------------------ the form

// Fields a page may edit, with their units and slider ranges (the loader
// checks every value; these only bound the sliders).
function lengthRange(d) { const R = Number(d.radius_mm) || 25; return [0, 2 * R]; }
const PRINT_FIELDS = [
  ['perimeters', 'perimeters', 0, 10, 1, ''],
  ['line_width_mm', 'line width', 0.2, 1.0, 0.01, 'mm'],
  ['top_bottom_layers', 'top/bottom layers', 0, 20, 1, ''],
  ['layer_height_mm', 'layer height', 0.05, 0.6, 0.01, 'mm'],
  ['infill', 'infill', 0, 100, 1, '%'],
  ['first_layer_height_mm', 'first layer', 0.05, 0.6, 0.01, 'mm'],
  ['first_layer_width_mm', 'first layer width', 0, 1.0, 0.01, 'mm'],
];
// PrusaSlicer 2.5's (tippe_print_defaults, include/tippe/print.h)
const PRINT_DEFAULTS = { perimeters: 2, line_width_mm: 0.45, top_bottom_layers: 4, layer_height_mm: 0.2, infill: 0.15,
                         first_layer_height_mm: 0.2, first_layer_width_mm: 0.42 };
// The sparse infill's patterns the print model follows (src/print/print_slicer.c's table; the
// shape-dependent ones, adaptive cubic, support cubic, lightning and 3D honeycomb, need the G-code)
const PATTERNS = ['gyroid', 'rectilinear', 'alignedrectilinear', 'monotonic', 'grid', 'triangles', 'stars',
                  'cubic', 'concentric', 'honeycomb'];
const PART_LENGTHS = ['radius_mm', 'inner_radius_mm', 'thickness_mm', 'height_mm', 'centre_radius_mm',
                      'radial_semi_mm', 'axial_semi_mm'];

function getPath(obj, path) {
  return path.split('.').reduce((o, k) => {
    if (o === undefined || o === null) return undefined;
    const m = k.match(/^(\w+)\[(\d+)\]$/);
    return m ? (o[m[1]] || [])[+m[2]] : o[k];
  }, obj);
}
function setPath(obj, path, value) {
  const keys = path.split('.');
  let o = obj;
  for (let i = 0; i < keys.length; i++) {
    const m = keys[i].match(/^(\w+)\[(\d+)\]$/);
    const last = i === keys.length - 1;
    if (m) {
      if (last) { o[m[1]][+m[2]] = value; return; }
      o = o[m[1]][+m[2]];
    } else {
      if (last) { o[keys[i]] = value; return; }
      if (typeof o[keys[i]] !== 'object' || o[keys[i]] === null) o[keys[i]] = {};
      o = o[keys[i]];
    }
  }
}

// A number's box and slider. A field in % (the infill, as PrusaSlicer shows it) keeps a
// fraction in the design and takes "20", "20%" or "20 %" in its box.
// An optional field (the weighed mass) may be left empty: the key is then left out.
function numberField(form, path, label, unit, lo, hi, step, value, optional) {
  const percent = unit === '%';
  if (value === undefined) value = '';
  if (percent && typeof value === 'number') value = +(value * 100).toPrecision(12);
  const row = document.createElement('div');
  row.className = 'field';
  row.dataset.path = path;
  const id = 'f-' + path.replace(/[^\w]/g, '_');
  const lab = document.createElement('label');
  lab.htmlFor = id; lab.textContent = label;
  const num = document.createElement('input');
  if (percent) { num.type = 'text'; num.inputMode = 'decimal'; num.className = 'percent'; }
  else num.type = 'number';
  num.id = id; num.step = step; num.value = value;
  num.setAttribute('aria-describedby', id + '-msg');
  num.title = `${label}: ${lo} .. ${hi} ${unit} on the slider; the loader checks any value`;
  const slider = document.createElement('input');
  slider.type = 'range';
  slider.min = value === '' ? lo : Math.min(lo, value); slider.max = value === '' ? hi : Math.max(hi, value);
  slider.step = step; slider.value = value === '' ? lo : value;
  slider.setAttribute('aria-label', label + ' (slider)');
  slider.tabIndex = -1; // the number box is the keyboard's
  const u = document.createElement('span'); u.className = 'unit'; u.textContent = unit;
  const msg = document.createElement('div'); msg.className = 'msg'; msg.id = id + '-msg'; msg.hidden = true;
  const changed = (v) => {
    const t = percent ? String(v).trim().replace(/\s*%$/, '') : v;
    const x = Number(t);
    noteEdit(path);
    setPath(state.design, path, optional && t === '' ? undefined
      : t === '' || !isFinite(x) ? v : percent ? +(x / 100).toPrecision(12) : x);
    edited();
  };
  num.addEventListener('input', () => { slider.value = percent ? num.value.replace(/\s*%\s*$/, '') : num.value; changed(num.value); });
  slider.addEventListener('input', () => { num.value = slider.value; changed(slider.value); });
  // the design's value shown again (a reset, an undo)
  row.show = (v) => {
    const shown = percent && typeof v === 'number' ? +(v * 100).toPrecision(12) : v;
    num.value = shown === undefined ? '' : shown; slider.value = shown === undefined ? lo : shown;
  };
  row.append(lab, slider, num, u, resetButton(path, label), msg);
  form.appendChild(row);
}

function selectField(form, path, label, options, value) {
  const row = document.createElement('div');
  row.className = 'field';
  row.dataset.path = path;
  const id = 'f-' + path.replace(/[^\w]/g, '_');
  const lab = document.createElement('label');
  lab.htmlFor = id; lab.textContent = label;
  const sel = document.createElement('select');
  sel.id = id;
  for (const [v, text] of options) {
    const o = document.createElement('option'); o.value = v; o.textContent = text; sel.appendChild(o);
  }
  sel.value = value === undefined ? '' : value;
  const msg = document.createElement('div'); msg.className = 'msg'; msg.hidden = true;
  // the empty choice leaves the key out (the design's default)
  sel.addEventListener('change', () => { noteEdit(null); setPath(state.design, path, sel.value === '' ? undefined : sel.value); edited(); });
  row.show = (v) => { sel.value = v === undefined ? '' : v; };
  row.append(lab, sel, resetButton(path, label), msg);
  form.appendChild(row);
}

function buildForm() {
  const d = state.design;
  const form = $('form');
  form.textContent = '';
  $('design-title').textContent = d.name || '(unnamed design)';
  const [, big] = lengthRange(d);
  let fs = document.createElement('fieldset');
  let lg = document.createElement('legend'); lg.textContent = 'Sphere and travel'; fs.appendChild(lg);
  numberField(fs, 'radius_mm', 'sphere radius', 'mm', 5, 60, 0.1, d.radius_mm);
  if (Array.isArray(d.travel_mm)) {
    numberField(fs, 'travel_mm[0]', 'travel from', 'mm', -big / 2, big / 2, 0.1, d.travel_mm[0]);
    numberField(fs, 'travel_mm[1]', 'travel to', 'mm', -big / 2, big / 2, 0.1, d.travel_mm[1]);
  }
  form.appendChild(fs);
  const mats = state.materials.map((m) => [m.name, `${m.name} (${m.density_g_cm3} g/cm³${m.printable ? ', printable' : ''})`]);
  (d.parts || []).forEach((p, i) => {
    fs = document.createElement('fieldset');
    lg = document.createElement('legend');
    lg.textContent = `${p.name} — ${p.shape}${p.void ? ', void' : ''}${p.moving ? ', moving' : ''}`;
    fs.appendChild(lg);
    for (const k of PART_LENGTHS)
      if (typeof p[k] === 'number')
        numberField(fs, `parts[${i}].${k}`, k.replace(/_mm$/, '').replace(/_/g, ' '), 'mm', 0, big, 0.1, p[k]);
    if (typeof p.z_mm === 'number' || p.moving)
      numberField(fs, `parts[${i}].z_mm`, p.moving ? 'z (from Z2)' : 'z', 'mm', -big / 2, big / 2, 0.1, p.z_mm || 0);
    if (typeof p.material === 'string' && !p.void)
      selectField(fs, `parts[${i}].material`, 'material', mats, p.material);
    if (p.moving && !p.void && p.shape === 'cylinder' && state.catalogue.length) catalogueField(fs, i, p);
    if (typeof p.density_g_cm3 === 'number')
      numberField(fs, `parts[${i}].density_g_cm3`, 'density', 'g/cm³', 0.1, 22.6, 0.01, p.density_g_cm3);
    // a hole a moving part (the screw) sits in: how it is printed (design-format.md, "Hole fit")
    if (p.void && (typeof p.fit === 'string' || (p.shape === 'cylinder' && d.parts.some((q) => q.moving && !q.void))))
      selectField(fs, `parts[${i}].fit`, 'hole fit', [['', '(none: build taps, export slides)'], ['tap', 'tap (tap drill)'],
                  ['insert', 'heat-set insert'], ['slide', 'sliding fit']], p.fit);
    if (p.print) {
      if (p.print === true) p.print = Object.assign({}, PRINT_DEFAULTS);
      for (const [k, label, lo, hi, step, unit] of PRINT_FIELDS)
        numberField(fs, `parts[${i}].print.${k}`, label, unit, lo, hi, step,
                    p.print[k] !== undefined ? p.print[k] : PRINT_DEFAULTS[k]);
      selectField(fs, `parts[${i}].print.pattern`, 'infill pattern', PATTERNS.map((x) => [x, x]), p.print.pattern || 'gyroid');
      numberField(fs, `parts[${i}].print.measured_mass_g`, 'weighed', 'g', 0, 200, 0.1, p.print.measured_mass_g, true);
      gcodeField(fs, i, p);
    } else if (!p.void && !p.moving && typeof p.material === 'string' &&
               (state.materials.find((m) => m.name === p.material) || {}).printable) {
      // a solid part of a printable material: printed instead, with the slicer's defaults
      const b = Object.assign(document.createElement('button'), { type: 'button', className: 'make-printed',
        textContent: 'Print it (slicer settings)' });
      b.addEventListener('click', () => {
        const d2 = JSON.parse(JSON.stringify(state.design));
        d2.parts[i].print = Object.assign({}, PRINT_DEFAULTS);
        editDesign(d2);
      });
      fs.appendChild(b);
    }
    form.appendChild(fs);
  });
}

function showFieldError(field, message) {
  for (const row of document.querySelectorAll('.field')) {
    row.classList.remove('bad');
    const m = row.querySelector('.msg'); if (m) { m.hidden = true; m.textContent = ''; }
  }
  const box = $('design-error');
  box.hidden = true;
  if (!message) return;
  const path = (field || '').replace(/^design\./, '');
  const row = path && document.querySelector(`.field[data-path="${CSS.escape(path)}"]`);
  if (row) {
    row.classList.add('bad');
    const m = row.querySelector('.msg'); m.textContent = message; m.hidden = false;
  } else {
    box.textContent = message; box.hidden = false;
  }
}

// ------------------------------------------------------------------ live sweep

let timer = null;
function schedule() {
  clearTimeout(timer);
  timer = null;
  // a launch, a film or a build shown was of the design before this edit
  clearLaunch();
  $('build-status').textContent = '';
  $('save-status').textContent = '';
  timer = setTimeout(() => { timer = null; refresh(); }, 150);
}

async function refresh() {
  const seq = ++state.seq;
  state.inFlight = true;
  $('busy').hidden = false;
  let r;
  // the verdict is asked with the sweep, not after it: the headline comes as soon as the
  // zones (each costs a sweep; a design the loader refuses answers both at once)
  // (a copy: the form edits state.design in place, and the advice is asked later)
  const design = JSON.parse(JSON.stringify(state.design));
  const verdict = api('/api/verdict', { design }).catch((e) => e);
  try { r = await api('/api/sweep', { design }); }
  catch (e) { if (seq === state.seq) { state.inFlight = false; $('busy').hidden = true; showFieldError(null, 'the server does not answer: ' + e.message); markStale('the server does not answer'); } return; }
  if (seq !== state.seq) return; // a newer edit is on its way
  state.inFlight = false;
  $('busy').hidden = true;
  if (!r.ok) {
    const msg = (r.json && r.json.error) || ('HTTP ' + r.status);
    showFieldError(r.json && r.json.field, msg);
    markStale('the design on the form does not load: ' + msg);
    if (state.pinWanted) { state.pinWanted = false; $('pin').textContent = 'Pin for compare'; }
    return;
  }
  showFieldError(null, null);
  markStale(null);
  state.sweepDesign = design;
  state.shownTitle = (design.name || state.name || 'design') + (isEdited() ? ' (edited)' : '');
  state.sweep = r.json;
  state.verdict = null;
  state.advice = null;
  if (state.adviceAbort) state.adviceAbort.abort(); // its design is no longer on screen
  state.adviceAbort = null;
  drawAll();
  if (state.z2 !== null) evalAt(state.z2);
  drawSection(design);
  if (state.pinWanted && timer === null) pin();
  sheetVerdict(++state.vseq, design, verdict);
}

// The results on screen are not of the design on the form (it does not load, or its
// own are on their way): greyed, and said whose they are; null when they are its own.
function markStale(why) {
  const res = $('results'), note = $('results-of');
  res.classList.toggle('stale', !!why && !!state.sweep);
  note.hidden = !why || !state.sweep;
  note.textContent = why && state.sweep ? `The results below are of ${state.shownTitle}, not of the design on the form: ${why}` : '';
}

// The build sheet's verdict of a valid design: "3-in-1" only where each behaviour can be
// set by hand (tippe build's rule) and its reason, as cheap as the sweep; then what the
// whole sheet adds (its launch checks, the changes one can buy: /api/advice, costly,
// kept by the server per design), asked once the verdict is shown and cancelled by the
// next edit. A bad edit after them does not drop them: they belong to the last valid
// design, still on screen.
async function sheetVerdict(vseq, design, asked) {
  let r = await asked;
  if (r instanceof Error) { if (vseq === state.vseq) $('verdict-text').textContent = 'the build sheet\'s verdict: the server does not answer'; return; }
  if (vseq !== state.vseq) return;
  if (!r.ok) { $('verdict-text').textContent = 'the build sheet\'s verdict: ' + ((r.json && r.json.error) || ('HTTP ' + r.status)); return; }
  state.verdict = r.json;
  drawVerdict();
  const ctl = new AbortController();
  state.adviceAbort = ctl;
  try { r = await api('/api/advice', { design }, ctl.signal); }
  catch (e) { if (vseq === state.vseq && !ctl.signal.aborted) { state.advice = { error: 'the server does not answer' }; drawVerdict(); } return; }
  if (vseq !== state.vseq) return;
  state.adviceAbort = null;
  state.advice = r.ok ? r.json : { error: (r.json && r.json.error) || ('HTTP ' + r.status) };
  drawVerdict();
}

function drawVerdict() {
  const b = state.verdict, a = state.advice, v = $('verdict'), t = $('verdict-text');
  t.textContent = '';
  $('sheet-more').textContent = '';
  drawHolds();
  if (!b) { // a spinner until this design's verdict arrives: never another verdict
    v.textContent = '…';
    v.className = 'verdict pending';
    v.setAttribute('aria-busy', 'true');
    return;
  }
  v.removeAttribute('aria-busy');
  v.textContent = b.verdict;
  v.className = 'verdict ' + (b.settable ? 'yes' : b.three_in_one ? 'paper' : 'no');
  // the sheet's text adds what its launch checks found at the poles; its verdict is this one
  const whole = a && !a.error && a.verdict === b.verdict;
  t.appendChild(document.createTextNode(whole ? a.text : b.text));
  if (!a) {
    const w = Object.assign(document.createElement('span'), { className: 'pending-note',
      textContent: b.settable ? ' checking the launches…' : ' finding changes one can buy…' });
    t.appendChild(w);
  } else if (a.error) {
    t.appendChild(document.createTextNode(' (the changes one can buy: ' + a.error + ')'));
  } else if (whole && a.advice.length) {
    t.appendChild(document.createTextNode(' Changes one can buy or set:'));
    t.appendChild(adviceList(a));
  }
  if (whole) drawSheetMore(a);
}

// Where the model does not hold, in the headline beside the verdict (its own state and
// colour): the Z2 where a part stands out of the sphere (the sweep's hatched spans) and,
// once the sheet's launch checks are in, a pole whose hole's rim a launch stands on.
function drawHolds() {
  const h = $('holds'), s = state.sweep, a = state.advice, where = [];
  drawMini(a && !a.error && a.model_holds_at_poles === false);
  if (s) {
    const spans = [];
    for (const z of s.zones) for (const [f, t] of z.model_invalid_mm || []) spans.push([f, t]);
    spans.sort((p, q) => p[0] - q[0]);
    const merged = [];
    for (const sp of spans) {
      const last = merged[merged.length - 1];
      if (last && sp[0] <= last[1] + 1e-9) last[1] = Math.max(last[1], sp[1]); else merged.push(sp.slice());
    }
    for (const [f, t] of merged) where.push(`Z2 ${fmt(f)} .. ${fmt(t)} mm (a part stands out of the sphere)`);
  }
  if (a && !a.error && a.model_holds_at_poles === false)
    where.push('at a pole: the launch checks stand on a hole\'s rim, the zones assume the sphere');
  h.hidden = where.length === 0;
  h.textContent = where.length ? 'the model does not hold: ' + where.join('; ') : '';
  h.dataset.state = where.length ? 'no' : 'yes';
}

// The verdict in one line at the top of a phone's screen, in view while the form scrolls.
function drawMini(poles) {
  const m = $('mini-verdict'), b = state.verdict;
  m.textContent = '';
  if (!b) { m.textContent = 'verdict: …'; return; }
  const v = Object.assign(document.createElement('span'), { className: 'verdict-word ' + (b.settable ? 'yes' : b.three_in_one ? 'paper' : 'no'),
                                                            textContent: b.verdict });
  m.append(v);
  const invalid = state.sweep && state.sweep.zones.some((z) => (z.model_invalid_mm || []).length);
  if (poles || invalid) m.append(Object.assign(document.createElement('span'), { className: 'mini-holds', textContent: 'model does not hold everywhere' }));
  if (state.sweep && state.sweep.three_in_one) m.append(` · narrowest ${fmt(state.sweep.narrowest_zone_mm)} mm`);
}

// What the whole sheet says beside its verdict: each launch check as its table words it,
// its warnings, and the poles' fixes with the --set lines that make them (a button tries
// one on the form).
function drawSheetMore(a) {
  const box = $('sheet-more');
  const list = (items) => {
    const ul = document.createElement('ul');
    for (const x of items) { const li = document.createElement('li'); li.append(...x); ul.appendChild(li); }
    return ul;
  };
  if (a.launch_checks && a.launch_checks.length) {
    box.appendChild(Object.assign(document.createElement('p'), { className: 'sheet-head',
      textContent: 'The build sheet\'s launch checks (tippe check\'s central hand launch at each set Z2):' }));
    box.appendChild(list(a.launch_checks.map((c) => [`${c.behaviour}: ${c.text}`])));
  }
  if (a.warnings && a.warnings.length) {
    const ul = list(a.warnings.map((w) => ['Warning: ' + w]));
    ul.className = 'warnings';
    box.appendChild(ul);
  }
  if (a.pole_fixes && a.pole_fixes.length) {
    box.appendChild(Object.assign(document.createElement('p'), { className: 'sheet-head',
      textContent: 'The poles\' fixes, each tried by sweeping the changed design:' }));
    const ul = list(a.pole_fixes.map((f) => {
      const code = Object.assign(document.createElement('code'), { className: 'set-line',
        textContent: f.set.map((x) => '--set ' + x).join(' ') });
      const btn = Object.assign(document.createElement('button'), { type: 'button', className: 'apply-fix',
        textContent: 'Try it on the form' });
      btn.addEventListener('click', () => applySets(f.set));
      return [`${f.fix} (${f.verdict}) `, code, ' ', btn];
    }));
    ul.id = 'pole-fixes';
    box.appendChild(ul);
  }
  if (a.notes && a.notes.length) {
    box.appendChild(Object.assign(document.createElement('p'), { className: 'sheet-head', textContent: 'The sheet\'s notes:' }));
    const ul = list(a.notes.map((n) => [n]));
    ul.id = 'sheet-notes';
    box.appendChild(ul);
  }
}

let resizeTimer = null;
window.addEventListener('resize', () => {
  clearTimeout(resizeTimer);
  resizeTimer = setTimeout(() => { if (state.sweep) drawAll(); }, 200);
});

function drawAll() {
  const s = state.sweep;
  drawVerdict();
  $('narrowest').textContent = s.three_in_one
    ? `narrowest zone ${fmt(s.narrowest_zone_mm)} mm (${s.narrowest_zone_family}); robust ${fmt(s.robust_narrowest_zone_mm)} mm`
    : `widest zones: I ${fmt(s.zone_widths_mm.I)} mm, II ${fmt(s.zone_widths_mm.II)} mm, III ${fmt(s.zone_widths_mm.III)} mm`;
  drawBar($('zonebar'), s, true);
  drawTable(s);
  drawPrinted(s);
  drawPlot(s);
  if (state.pinned) drawPinned();
}

// A phone's width (the page's one-column layout below 520 px, style.css).
const phone = () => window.matchMedia('(max-width: 520px)').matches;
const MM_PX = 24; // a mm of Z2 on a phone's bar: a finger's tap (about 6 mm) sets it to 0.25 mm

// What the bar lays over its zones, shared with its legend so that a key is what the bar
// draws: the tolerance bands, the travel beyond the physical one, and the hatching where a
// part stands out of the sphere.
const OVERLAY = { band: { fill: '#1d232a', opacity: 0.28 }, pale: { fill: '#fff', opacity: 0.6 } };
function hatchPattern(defs, id) {
  const pat = el('pattern', { id, width: 6, height: 6, patternUnits: 'userSpaceOnUse', patternTransform: 'rotate(45)' }, defs);
  el('rect', { width: 6, height: 6, fill: '#ffffff99' }, pat);
  el('line', { x1: 0, y1: 0, x2: 0, y2: 6, stroke: '#555', 'stroke-width': 2 }, pat);
}

// The bar's legend, drawn with the bar's own fills: each group's colour, and each overlay
// on a zone's colour as the bar lays it.
function drawLegend() {
  const box = $('legend');
  box.textContent = '';
  const key = (draw, words) => {
    const svg = el('svg', { width: 28, height: 14, viewBox: '0 0 28 14', class: 'key', 'aria-hidden': 'true' });
    draw(svg);
    const span = document.createElement('span');
    span.className = 'legend-item';
    span.append(svg, ...words);
    box.appendChild(span);
  };
  for (const [g, words] of [['I', 'stays up (I)'], ['IIb', 'flips (IIa, IIb, IIc)'], ['III', 'hangs (III)']])
    key((svg) => el('rect', { width: 28, height: 14, fill: GROUP_COLOR[g], 'data-key': 'group' }, svg), [words]);
  const under = (svg) => el('rect', { width: 28, height: 14, fill: GROUP_COLOR.IIb }, svg);
  key((svg) => { under(svg); el('rect', { x: 9, width: 10, height: 14, fill: OVERLAY.band.fill, opacity: OVERLAY.band.opacity, 'data-key': 'band' }, svg); },
      ['tolerance ', term('band'), ' of a boundary']);
  key((svg) => { under(svg); el('rect', { width: 28, height: 14, fill: OVERLAY.pale.fill, opacity: OVERLAY.pale.opacity, 'data-key': 'pale' }, svg); },
      ['beyond the physical travel']);
  key((svg) => { under(svg); hatchPattern(el('defs', {}, svg), 'hatch-legend'); el('rect', { width: 28, height: 14, fill: 'url(#hatch-legend)', 'data-key': 'hatch' }, svg); },
      ['a part stands out of the sphere: the model does not apply']);
}

// The zone bar: zones along Z2, tolerance bands at their boundaries, the
// travel beyond the physical one and where the model does not apply hatched.
function drawBar(box, s, clickable) {
  box.textContent = '';
  const H = 92, L = 40, R = 20, top = 18, h = 34;
  const [a, b] = s.sweep_mm;
  // on a phone the bar is drawn at its pixels (its text 14 px, not scaled down) and at
  // least MM_PX to a mm of Z2, so that a finger sets Z2 to the mm; it scrolls sideways
  const W = phone() ? Math.max(box.clientWidth || 360, L + R + MM_PX * (b - a)) : 900;
  const x = (z) => L + (W - L - R) * (z - a) / (b - a);
  const svg = el('svg', { viewBox: `0 0 ${W} ${H}`, role: 'img', 'aria-label': 'zones along Z2' }, box);
  if (phone()) { svg.style.width = W + 'px'; svg.style.maxWidth = 'none'; }
  const defs = el('defs', {}, svg);
  hatchPattern(defs, 'hatch' + box.id);
  for (const z of s.zones) {
    const r = el('rect', { x: x(z.z2_from_mm), y: top, width: Math.max(0.5, x(z.z2_to_mm) - x(z.z2_from_mm)), height: h,
                           fill: GROUP_COLOR[z.group] || '#999', opacity: z.within_travel ? 1 : 0.35 }, svg);
    r.addEventListener('mousemove', (ev) => showTip(ev, `${z.group} (${GROUP_MEANING[z.group] || ''}) ${fmt(z.z2_from_mm)} .. ${fmt(z.z2_to_mm)} mm, width ${fmt(z.width_mm)} mm, robust ${fmt(z.robust_width_mm)} mm`));
    r.addEventListener('mouseleave', hideTip);
    if (x(z.z2_to_mm) - x(z.z2_from_mm) > 26)
      el('text', { x: (x(z.z2_from_mm) + x(z.z2_to_mm)) / 2, y: top + h / 2 + 4, 'text-anchor': 'middle', fill: '#fff', 'font-weight': 600, class: 'on-zone' }, svg, z.group);
    for (const [f, t] of z.model_invalid_mm || [])
      el('rect', { x: x(f), y: top, width: Math.max(0.5, x(t) - x(f)), height: h, fill: `url(#hatch${box.id})` }, svg);
  }
  for (const bd of s.bands || []) {
    if (!isFinite(bd.band_mm)) continue;
    const r = el('rect', { x: x(bd.z2_mm - bd.band_mm), y: top - 5, width: Math.max(1, x(bd.z2_mm + bd.band_mm) - x(bd.z2_mm - bd.band_mm)),
                           height: h + 10, fill: OVERLAY.band.fill, opacity: OVERLAY.band.opacity }, svg);
    r.addEventListener('mousemove', (ev) => showTip(ev, `${bd.boundary} at ${fmt(bd.z2_mm)} mm ± ${fmt(bd.band_mm)} mm (tolerances)`));
    r.addEventListener('mouseleave', hideTip);
  }
  const [pa, pb] = s.physical_travel_mm;
  for (const [f, t] of [[a, Math.min(pa, b)], [Math.max(pb, a), b]])
    if (t > f) el('rect', { x: x(f), y: top, width: x(t) - x(f), height: h, fill: OVERLAY.pale.fill, opacity: OVERLAY.pale.opacity }, svg);
  // axis
  const step = niceStep((b - a) / 8);
  for (let z = Math.ceil(a / step) * step; z <= b + 1e-9; z += step) {
    el('line', { x1: x(z), x2: x(z), y1: top + h, y2: top + h + 5, stroke: '#555' }, svg);
    el('text', { x: x(z), y: top + h + 18, 'text-anchor': 'middle' }, svg, fmt(z, step < 1 ? 1 : 0));
  }
  el('text', { x: W - R, y: top - 5, 'text-anchor': 'end' }, svg, 'Z2 mm');
  if (state.z2 !== null && clickable)
    el('line', { x1: x(state.z2), x2: x(state.z2), y1: top - 8, y2: top + h + 8, stroke: '#000', 'stroke-width': 2 }, svg);
  if (clickable) {
    svg.addEventListener('click', (ev) => {
      const p = svg.createSVGPoint(); p.x = ev.clientX; p.y = ev.clientY;
      const q = p.matrixTransform(svg.getScreenCTM().inverse());
      const z = a + (b - a) * (q.x - L) / (W - L - R);
      if (z >= a && z <= b) pointAt(Math.round(z * 100) / 100);
    });
  }
}

function niceStep(raw) {
  const p = Math.pow(10, Math.floor(Math.log10(raw)));
  for (const m of [1, 2, 5, 10]) if (m * p >= raw) return m * p;
  return 10 * p;
}

// The zone table as tippe sweep prints it: each run with the boundary it ends on and its
// notes (which side is down, where the model does not apply), so that two rows of one
// group say why they are two.
function drawTable(s) {
  const t = $('zones');
  t.textContent = '';
  const head = t.insertRow();
  const th = (x) => { const c = document.createElement('th'); c.append(x); head.appendChild(c); };
  ['zone', 'from mm', 'to mm', 'width mm'].forEach(th);
  th(term('robust', 'robust mm'));
  th(term('band', 'band from ± mm'));
  th(term('band', 'band to ± mm'));
  th('ends on');
  th('notes');
  // which side is down is said where it differs between rows, as the command does
  const mixed = new Set(s.zones.map((z) => z.com_side)).size > 1;
  s.zones.forEach((z, i) => {
    const r = t.insertRow();
    const c = r.insertCell();
    c.innerHTML = '<span class="swatch"></span>';
    c.firstChild.style.background = GROUP_COLOR[z.group] || '#999';
    c.appendChild(document.createTextNode(`${z.group} ${GROUP_MEANING[z.group] || ''}${z.within_travel ? '' : ' (beyond the travel)'}`));
    for (const v of [z.z2_from_mm, z.z2_to_mm, z.width_mm, z.robust_width_mm, z.band_from_mm, z.band_to_mm])
      r.insertCell().textContent = fmt(v, 3);
    const e = r.insertCell();
    e.className = 'ends';
    e.textContent = (z.ends_on || []).join(', ') || (i + 1 === s.zones.length ? '(end of sweep)' : '(physical travel)');
    const notes = [];
    if (mixed) notes.push(z.com_side > 0 ? '+z side down' : z.com_side < 0 ? '-z side down' : 'balanced');
    for (const [f, to] of z.model_invalid_mm || []) notes.push(`MODEL INVALID ${fmt(f, 3)} .. ${fmt(to, 3)} mm`);
    const n = r.insertCell();
    n.className = 'notes';
    n.textContent = notes.join('; ');
    if ((z.model_invalid_mm || []).length) r.classList.add('invalid');
    if (!z.within_travel) r.classList.add('out');
  });
}

// Figure 7: A/C - 1 and the lines +-eps/R, -(eps/R)^2 over Z2.
function drawPlot(s) {
  const box = $('plot');
  box.textContent = '';
  const c = s.curve;
  // on a phone: drawn at its pixels, so that its text is 14 px
  const W = phone() ? Math.max(box.clientWidth || 360, 320) : 900, H = phone() ? 260 : 300;
  const L = 60, R = 20, T = 12, B = 34;
  const [a, b] = s.sweep_mm;
  const k1 = c.A_over_C.map((k) => k - 1);
  const e = c.eps_over_R_signed.map(Math.abs);
  const all = k1.concat(e, e.map((v) => -v));
  let lo = Math.min(...all), hi = Math.max(...all);
  const pad = 0.05 * (hi - lo || 1); lo -= pad; hi += pad;
  const x = (z) => L + (W - L - R) * (z - a) / (b - a);
  const y = (v) => T + (H - T - B) * (hi - v) / (hi - lo);
  const svg = el('svg', { viewBox: `0 0 ${W} ${H}`, role: 'img', 'aria-label': 'A/C - 1 and eps/R along Z2' }, box);
  el('line', { x1: L, x2: W - R, y1: y(0), y2: y(0), stroke: '#aaa' }, svg);
  const line = (vals, color, dash, label) => {
    const d = vals.map((v, i) => `${i ? 'L' : 'M'}${x(c.z2_mm[i]).toFixed(1)},${y(v).toFixed(1)}`).join('');
    el('path', { d, fill: 'none', stroke: color, 'stroke-width': 2, 'stroke-dasharray': dash || '' }, svg);
    return label;
  };
  line(k1, '#1f5fa8', '', 'A/C - 1');
  line(e, '#a23a8f', '6 4', '+eps/R');
  line(e.map((v) => -v), '#3f8f4f', '6 4', '-eps/R');
  line(e.map((v) => -v * v), '#777', '2 3', '-(eps/R)^2');
  const keys = [['A/C − 1', '#1f5fa8', ''], ['+eps/R', '#a23a8f', '6 4'], ['−eps/R', '#3f8f4f', '6 4'], ['−(eps/R)²', '#777', '2 3']];
  const kw = (W - L - R) / 4 < 110 ? (W - L - R) / 2 : 120; // two rows of keys on a phone
  keys.forEach(([t, col, dash], i) => {
    const kx = L + 10 + (i % (kw < 110 ? 2 : 4)) * kw, ky = T + 10 + (kw < 110 ? Math.floor(i / 2) * 18 : 0);
    el('line', { x1: kx, x2: kx + 30, y1: ky, y2: ky, stroke: col, 'stroke-width': 2, 'stroke-dasharray': dash }, svg);
    el('text', { x: kx + 36, y: ky + 4 }, svg, t);
  });
  const step = niceStep((b - a) / 8);
  for (let z = Math.ceil(a / step) * step; z <= b + 1e-9; z += step)
    el('text', { x: x(z), y: H - B + 16, 'text-anchor': 'middle' }, svg, fmt(z, step < 1 ? 1 : 0));
  el('text', { x: W - R, y: H - 4, 'text-anchor': 'end' }, svg, 'Z2 mm');
  const vstep = niceStep((hi - lo) / 6);
  for (let v = Math.ceil(lo / vstep) * vstep; v <= hi; v += vstep)
    el('text', { x: L - 6, y: y(v) + 4, 'text-anchor': 'end' }, svg, fmt(v, vstep < 0.01 ? 3 : 2));
  const cursor = el('line', { x1: 0, x2: 0, y1: T, y2: H - B, stroke: '#000', opacity: 0 }, svg);
  svg.addEventListener('mousemove', (ev) => {
    const p = svg.createSVGPoint(); p.x = ev.clientX; p.y = ev.clientY;
    const q = p.matrixTransform(svg.getScreenCTM().inverse());
    const i = Math.max(0, Math.min(c.z2_mm.length - 1, Math.round((q.x - L) / (W - L - R) * (c.z2_mm.length - 1))));
    cursor.setAttribute('x1', x(c.z2_mm[i])); cursor.setAttribute('x2', x(c.z2_mm[i])); cursor.setAttribute('opacity', 0.5);
    showTip(ev, `Z2 ${fmt(c.z2_mm[i])} mm: A/C − 1 = ${fmt(k1[i], 4)}, eps/R = ${fmt(e[i], 4)}, mass ${fmt(c.mass_kg[i] * 1e3, 1)} g`);
  });
  svg.addEventListener('mouseleave', () => { cursor.setAttribute('opacity', 0); hideTip(); });
}

// ------------------------------------------------------------------ a point

function pointAt(z2) {
  if (state.z2 !== z2 || Number($('z2').value) !== z2) clearLaunch();
  state.z2 = z2;
  $('z2').value = z2;
  drawBar($('zonebar'), state.sweep, true);
  evalAt(z2);
  if (state.sweepDesign) drawSection(state.sweepDesign);
}

async function evalAt(z2) {
  const r = await api('/api/eval', { design: state.design, z2_mm: z2 });
  if (!r.ok) { $('point').textContent = r.json ? r.json.error : 'HTTP ' + r.status; return; }
  const o = r.json;
  $('point').textContent = `Z2 ${fmt(z2)} mm: group ${o.subgroup} (${GROUP_MEANING[o.subgroup] || GROUP_MEANING[o.group] || ''}), ` +
    `mass ${fmt(o.mass_kg * 1e3, 1)} g, A/C ${fmt(o.A_over_C, 4)}, eps/R ${fmt(o.eps_over_R, 4)}` +
    (o.model_valid ? '' : ` — model invalid here: ${o.protrusion.part} stands out of the sphere`);
}

// ------------------------------------------------------------------ a launch

// The launch the boxes ask for, or {error} naming the empty or bad box: an empty box is
// refused, never read as 0.
function launchRequest() {
  const zt = $('z2').value.trim(), st = $('spin').value.trim();
  if (zt === '' || !isFinite(Number(zt)))
    return { error: 'Z2: type where the weight is (mm), or click the bar' };
  if (st === '' || !isFinite(Number(st)))
    return { error: 'spin: type the launch\'s spin in rev/s (0.1 .. 100)' };
  // "patch:TABLE": the spinning contact patch, Hertz's radius on that table
  const [law, table] = $('friction').value.split(':');
  const req = { design: state.design, z2_mm: Number(zt), spin_rev_s: Number(st), friction: law };
  if (table) req.table = table;
  return req;
}

// What the launch ran, first on its line: "Z2 8.95 mm, 15 rev/s, viscous (paper, 2.3 s/m)".
function launchWhat(req) {
  const f = $('friction');
  return `Z2 ${req.z2_mm} mm, ${req.spin_rev_s} rev/s, ${f.options[f.selectedIndex].textContent}`;
}

// How a verdict was decided, in words (docs/dynamics.md, "Proved verdicts"; the patch
// law's, "Patch friction"): the decision time is when it was proved, not the run's length.
function decidedText(o) {
  const t = o.t_s, when = !(t > 0) ? 'at launch (t = 0 s)' : `at t = ${fmt(t, 2)} s`;
  const flip = o.t_flip_s !== null && o.t_flip_s > t ? ` (before the flip at ${fmt(o.t_flip_s, 2)} s)` : '';
  const span = document.createElement('span');
  switch (o.decided_by) {
  case 'trapped':
    span.append('proved ' + when + flip + ': its energy is ', term('trapped'), ' in the well it ends in');
    break;
  case 'energy_cone': span.append(`proved ${when} by the energy alone: it can no longer climb past 0.25 rad`); break;
  case 'lost_contact': span.append(`it leaves the table ${when}`); break;
  case 'flat_well': span.append(`not decided: confined to a flat well ${when}, no end state can be proved`); break;
  case 'rolling': span.append(`decided ${when}: it sticks and rolls for ever (Coulomb friction)`); break;
  case 'budget': span.append(`not decided: the integration's step budget ran out ${when}`); break;
  case 't_end': span.append(`not decided by the end of the run (t = ${fmt(t, 0)} s)`); break;
  case 'observed':
    span.append(`observed at the end of the ${fmt(t, 0)} s run, not proved: under the `, term('patch law'),
                ' no energy bound holds');
    break;
  default: span.append(`decided by ${o.decided_by} ${when}`);
  }
  return span;
}

// The command's contact lines (tippe check's "contact" and "rim"): a part standing out of
// the sphere makes the verdict INVALID; a hole's rim at a pole is modelled.
function contactText(o) {
  const out = [];
  if (o.model_valid === false && o.protrusion)
    out.push(`contact INVALID: '${o.protrusion.part}' stands out of the sphere here, the top rests on it (the model assumes the sphere)`);
  const c = o.on_polar_cap;
  if (c && (c.start || c.end || (c.first_s !== null && c.first_s !== undefined))) {
    const where = c.start && c.end ? `starts on the rim at ${c.start} and ends on it at ${c.end}`
      : c.start ? `starts on the hole's rim at ${c.start}` : c.end ? `ends on the hole's rim at ${c.end}`
      : 'touches a hole\'s rim';
    out.push(`on the rim (modelled): it ${where}; on a rim ${fmt(c.time_s, 3)} s in all (the contact follows the rim; the zones assume the sphere)`);
  }
  return out;
}

// The launch's inputs changed: its result, plot and film were of the old ones.
function clearLaunch() {
  for (const id of ['check-result', 'theta-plot', 'film-box']) $(id).textContent = '';
  delete $('check-result').dataset.verdict;
  state.lseq++;
}

async function checkLaunch() {
  const out = $('check-result');
  const req = launchRequest();
  clearLaunch();
  const seq = state.lseq;
  if (req.error) { out.textContent = req.error; out.classList.add('error'); return; }
  out.classList.remove('error');
  out.textContent = launchWhat(req) + ': integrating…';
  const r = await api('/api/check', req);
  if (seq !== state.lseq) return; // its inputs changed meanwhile
  if (!r.ok) { out.textContent = launchWhat(req) + ': ' + (r.json ? r.json.error : 'HTTP ' + r.status); return; }
  const o = r.json;
  const fall = (x) => (x.t_fall_s !== null && x.t_fall_s !== undefined ? `, back below 90° at ${fmt(x.t_fall_s, 1)} s` : '');
  out.textContent = '';
  const head = document.createElement('div');
  head.id = 'check-line';
  head.append(`${launchWhat(req)}: ${o.verdict}` + (o.t_flip_s !== null ? `, flips at t = ${fmt(o.t_flip_s, 2)} s` : '') + fall(o) + ', ',
              decidedText(o), `; theory: ${o.theory.prediction || '—'}`);
  out.appendChild(head);
  for (const w of contactText(o))
    out.appendChild(Object.assign(document.createElement('div'), { className: 'check-warning', textContent: w }));
  const rs = o.radius_sensitivity;
  if (rs) { // the patch law: the same launch at 1/F and F times the uncertain patch radius
    const runs = rs.runs.map((x) => `${+x.factor.toPrecision(3)}× (${fmt(x.patch_mm, 3)} mm): ` +
      (x.ran ? x.verdict + (x.t_flip_s !== null ? `, flips at ${fmt(x.t_flip_s, 2)} s` : ', no flip') + fall(x) : 'not run'));
    const line = document.createElement('div');
    line.id = 'radius-result';
    line.textContent = 'patch radius ' + runs.join('; ') + ' — ' +
      (rs.robust ? 'robust to the radius' : rs.changed ? 'NOT robust to the radius' : 'robustness not known (a radius was not run)');
    out.appendChild(line);
  }
  out.dataset.verdict = o.verdict;
  drawTheta(o.theta_samples);
}

function drawTheta(ts) {
  const box = $('theta-plot');
  box.textContent = '';
  if (!ts || !ts.t_s.length) return;
  const W = 900, H = 200, L = 60, R = 20, T = 10, B = 30;
  const t1 = ts.t_s[ts.t_s.length - 1] || 1;
  const x = (t) => L + (W - L - R) * t / t1;
  const y = (th) => T + (H - T - B) * (1 - th / Math.PI);
  const svg = el('svg', { viewBox: `0 0 ${W} ${H}`, role: 'img', 'aria-label': 'theta over time' }, box);
  for (const deg of [0, 90, 180]) {
    el('line', { x1: L, x2: W - R, y1: y(deg * Math.PI / 180), y2: y(deg * Math.PI / 180), stroke: '#ddd' }, svg);
    el('text', { x: L - 6, y: y(deg * Math.PI / 180) + 4, 'text-anchor': 'end' }, svg, deg + '°');
  }
  const d = ts.t_s.map((t, i) => `${i ? 'L' : 'M'}${x(t).toFixed(1)},${y(ts.theta_rad[i]).toFixed(1)}`).join('');
  el('path', { d, fill: 'none', stroke: '#1f5fa8', 'stroke-width': 2 }, svg);
  el('text', { x: W - R, y: H - 6, 'text-anchor': 'end' }, svg, `t s (0 .. ${fmt(t1, 1)})`);
  el('text', { x: L + 6, y: T + 12 }, svg, 'theta (tilt)');
}

async function film() {
  const box = $('film-box');
  const req = launchRequest();
  if (req.error) { box.textContent = req.error; return; }
  box.textContent = 'filming ' + launchWhat(req) + '…';
  const r = await api('/api/animate', req);
  if (!r.ok || !r.blob) { box.textContent = r.json ? r.json.error : 'HTTP ' + r.status; return; }
  box.textContent = '';
  const url = URL.createObjectURL(r.blob);
  if (r.type.startsWith('video/')) {
    const v = document.createElement('video');
    v.src = url; v.controls = true; v.autoplay = true; v.loop = true; v.muted = true;
    box.appendChild(v);
  } else {
    const img = document.createElement('img'); img.src = url; img.alt = 'the launch as a film'; box.appendChild(img);
  }
}

// ------------------------------------------------------------------ build

async function build() {
  const st = $('build-status');
  st.textContent = 'building…';
  const name = stem();
  const r = await api('/api/build', { design: state.design, name });
  if (!r.ok || !r.blob) { st.textContent = r.json ? r.json.error : 'HTTP ' + r.status; return; }
  const a = document.createElement('a');
  a.href = URL.createObjectURL(r.blob);
  a.download = name + '-build.zip';
  document.body.appendChild(a); a.click(); a.remove();
  st.textContent = `downloaded ${a.download} (${Math.round(r.blob.size / 1024)} KiB)`;
}

// ------------------------------------------------------------------ compare

// Pin the design whose zones are shown, with them; pressed while a sweep of a newer edit
// runs, the pin waits for that sweep and pins its design.
function pin() {
  if (timer !== null || state.inFlight) { state.pinWanted = true; $('pin').textContent = 'Pinning when the zones are in…'; return; }
  if (!state.sweep) return;
  state.pinWanted = false;
  $('pin').textContent = 'Pin for compare';
  state.pinned = { design: state.sweepDesign, sweep: state.sweep, title: state.shownTitle };
  $('pinned').hidden = false;
  drawPinned();
}

function drawPinned() {
  const p = state.pinned, s = state.sweep;
  $('pinned-title').textContent = `(${p.title})`;
  drawBar($('zonebar-pinned'), p.sweep, false);
  const t = $('diff');
  t.textContent = '';
  const head = t.insertRow();
  for (const h of ['', 'pinned', 'now', 'change']) head.appendChild(Object.assign(document.createElement('th'), { textContent: h }));
  const rows = [
    ['3-in-1 on paper', p.sweep.three_in_one ? 'yes' : 'no', s.three_in_one ? 'yes' : 'no', ''],
    ['narrowest zone mm', p.sweep.narrowest_zone_mm, s.narrowest_zone_mm],
    ['robust narrowest mm', p.sweep.robust_narrowest_zone_mm, s.robust_narrowest_zone_mm],
  ];
  for (const g of ['I', 'II', 'III'])
    rows.push([`zone ${g} mm (robust)`, p.sweep.robust_zone_widths_mm[g], s.robust_zone_widths_mm[g]]);
  for (const [name, a, b, c] of rows) {
    const r = t.insertRow();
    r.insertCell().textContent = name;
    r.insertCell().textContent = typeof a === 'number' ? fmt(a, 3) : a;
    r.insertCell().textContent = typeof b === 'number' ? fmt(b, 3) : b;
    r.insertCell().textContent = c !== undefined ? c : (typeof a === 'number' && typeof b === 'number' ? (b - a >= 0 ? '+' : '') + fmt(b - a, 3) : '');
  }
}

// ------------------------------------------------------------------ designs

async function openShipped(name) {
  const r = await api('/api/designs/' + encodeURIComponent(name));
  if (!r.ok) { showFieldError(null, r.json ? r.json.error : 'HTTP ' + r.status); return; }
  openDesign(r.json, name, 'shipped');
}

function openDesign(d, name, source, original) {
  state.design = d;
  state.name = name || '';
  state.source = source || 'shipped';
  state.undo = [];
  state.lastEdit = { path: null, t: 0 };
  state.z2 = null;
  buildForm(); // a "print": true becomes its settings: not an edit
  state.original = original || JSON.stringify(state.design);
  markEdited();
  keepEdit();
  markStale(`loading ${d.name || state.name || 'the design'}…`);
  refresh();
}

function loadText(text, name, source) {
  let d;
  try { d = JSON.parse(text); } catch (e) { showFieldError(null, 'not valid JSON: ' + e.message); return; }
  if (!d || typeof d !== 'object' || Array.isArray(d)) { showFieldError(null, 'not a design: a design file is a JSON object'); return; }
  if (!mayDiscard()) return;
  openDesign(d, name, source);
}

async function start() {
  $('form').addEventListener('submit', (ev) => ev.preventDefault());
  drawLegend();
  for (const a of document.querySelectorAll('abbr[data-term]')) a.title = TERMS[a.dataset.term];
  $('narrowest').title = TERMS.narrowest;
  const [list, mats, cat] = await Promise.all([api('/api/designs'), api('/api/materials'), api('/api/catalogue')]);
  state.materials = mats.ok ? mats.json.materials : [];
  state.catalogue = cat.ok ? cat.json.items : [];
  const pick = $('design-pick');
  for (const d of list.json.designs) {
    const o = document.createElement('option'); o.value = d.name; o.textContent = `${d.name} — ${d.title}`; pick.appendChild(o);
  }
  let picked = null;
  pick.addEventListener('focus', () => { picked = pick.value; });
  pick.addEventListener('change', () => {
    if (!mayDiscard()) { pick.value = picked !== null ? picked : state.name; return; }
    picked = pick.value;
    openShipped(pick.value);
  });
  $('design-file').addEventListener('change', async (ev) => {
    const f = ev.target.files[0]; if (f) loadText(await f.text(), f.name.replace(/\.json$/, ''), 'file');
    ev.target.value = '';
  });
  $('design-file-label').addEventListener('keydown', (ev) => { if (ev.key === 'Enter' || ev.key === ' ') { ev.preventDefault(); $('design-file').click(); } });
  $('design-paste').addEventListener('click', () => { $('paste-box').hidden = false; $('paste-text').focus(); });
  $('paste-cancel').addEventListener('click', () => { $('paste-box').hidden = true; });
  $('paste-load').addEventListener('click', () => { $('paste-box').hidden = true; loadText($('paste-text').value, '', 'pasted'); });
  $('undo').addEventListener('click', undo);
  $('design-save').addEventListener('click', save);
  $('pin').addEventListener('click', pin);
  $('unpin').addEventListener('click', () => { state.pinned = null; $('pinned').hidden = true; });
  $('check').addEventListener('click', checkLaunch);
  $('film').addEventListener('click', film);
  $('build').addEventListener('click', build);
  $('z2').addEventListener('change', () => { const t = $('z2').value.trim(); if (t !== '' && isFinite(Number(t))) pointAt(Number(t)); });
  for (const id of ['z2', 'spin', 'friction'])
    for (const ev of ['input', 'change']) $(id).addEventListener(ev, clearLaunch);
  // a link to an edited design opened over this page (only its fragment differs)
  window.addEventListener('hashchange', () => {
    const k = keptFromHash();
    if (k && mayDiscard()) { keptGcodes(k); openDesign(k.design, k.from, k.source, k.original); }
  });
  const want = new URLSearchParams(location.search).get('design');
  // an edited design: the link's (#edit=...), else the last one this browser kept
  // (not when the link names a shipped design)
  let kept = keptFromHash();
  try {
    if (!kept && !want) kept = JSON.parse(localStorage.getItem('tippe-edit'));
  } catch (e) { kept = null; }
  if (kept && kept.design && typeof kept.design === 'object') {
    if (list.json.designs.find((d) => d.name === kept.from)) pick.value = kept.from;
    keptGcodes(kept);
    openDesign(kept.design, kept.from, kept.source, kept.original);
    return;
  }
  const first = list.json.designs.find((d) => d.name === want) ? want
    : (list.json.designs.find((d) => d.name === 'm12-setscrew') ? 'm12-setscrew' : list.json.designs[0].name);
  pick.value = first;
  openShipped(first);
}

start();
