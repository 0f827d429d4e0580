// tippe serve's page, the maker's loop (issue 37): keeping every edit (undo, a field's
// reset, the edited design in the URL and local storage, asking before one is dropped,
// the files' stem), a fix tried on the form, the print taken back in (a sliced G-code
// uploaded, a catalogue screw) and the section drawing. Loaded before app.js, whose
// state, helpers and start() these use when they run (docs/serve.md).
'use strict';

// Before a change: the version it changes goes on the undo list (a run of keystrokes in
// one field within a second is one step).
function noteEdit(path) {
  const now = Date.now();
  if (path === null || path !== state.lastEdit.path || now - state.lastEdit.t > 1000)
    state.undo.push(JSON.stringify(state.design));
  if (state.undo.length > 100) state.undo.shift();
  state.lastEdit = { path, t: now };
}

// After a change: the fields that differ from the design as opened show their reset, the
// edited design is kept (the URL, which reopens it, and this browser's storage), and the
// results follow.
function edited() {
  markEdited();
  keepEdit();
  schedule();
}

function isEdited() { return state.original !== null && JSON.stringify(state.design) !== state.original; }

function markEdited() {
  const o = state.original ? JSON.parse(state.original) : null;
  for (const row of document.querySelectorAll('#form .field')) {
    const differs = o && JSON.stringify(getPath(state.design, row.dataset.path)) !== JSON.stringify(getPath(o, row.dataset.path));
    row.classList.toggle('edited', !!differs);
    const b = row.querySelector('.reset'); if (b) b.hidden = !differs;
  }
  $('undo').disabled = state.undo.length === 0;
  $('design-title').textContent = (state.design.name || '(unnamed design)') + (isEdited() ? ' (edited)' : '');
}

// The edited design in the URL's fragment (a link that reopens it; never sent to the
// server) and in local storage (the last edit survives a closed tab).
function keepEdit() {
  const kept = { from: state.name, source: state.source, original: state.original, design: state.design };
  // the names of the uploads it names: Save JSON names the files by them after a reopen
  for (const p of state.design.parts || []) {
    const g = p && p.print && typeof p.print === 'object' ? p.print.gcode : null;
    if (typeof g === 'string' && state.gcodeFiles[g]) {
      kept.gcodes = kept.gcodes || {};
      kept.gcodes[g] = { file: state.gcodeFiles[g], shown: state.gcodeNames[g] };
    }
  }
  const frag = isEdited() ? '#edit=' + encodeURIComponent(JSON.stringify(kept)) : '';
  history.replaceState(null, '', location.pathname + location.search + frag);
  try {
    if (isEdited()) localStorage.setItem('tippe-edit', JSON.stringify(kept));
    else localStorage.removeItem('tippe-edit');
  } catch (e) { /* storage off: the URL keeps it */ }
}

// The uploads' names a kept edit carries, taken back (strings only).
function keptGcodes(kept) {
  for (const [g, v] of Object.entries(kept.gcodes || {}))
    if (g.startsWith('upload:') && v && typeof v.file === 'string') {
      state.gcodeFiles[g] = v.file;
      if (typeof v.shown === 'string') state.gcodeNames[g] = v.shown;
    }
}

function undo() {
  if (!state.undo.length) return;
  state.design = JSON.parse(state.undo.pop());
  state.lastEdit = { path: null, t: 0 };
  buildForm();
  edited();
}

// A whole new version of the design on the form (a fix tried): the form is made again
// from it and the results follow.
function editDesign(d) {
  noteEdit(null);
  state.design = d;
  buildForm();
  edited();
}

// Before the design on the form is replaced: its edits are kept only if the maker says so.
function mayDiscard() {
  return !isEdited() || confirm(`Discard your edits to ${state.design.name || state.name || 'this design'}? ` +
                                '(Cancel keeps them; Save JSON downloads them.)');
}

// The files' stem: the shipped design's or the opened file's name ("-edited" once edited),
// a pasted design's from its name field.
function stem() {
  const slug = (t) => String(t || '').toLowerCase().replace(/[^a-z0-9_-]+/g, '-').replace(/^-+|-+$/g, '').slice(0, 48);
  const base = state.source === 'pasted' ? (slug(state.design.name) || 'design') : (slug(state.name) || 'design');
  return state.source !== 'pasted' && isEdited() ? base + '-edited' : base;
}

// The edited design a link carries (#edit=...), or null.
function keptFromHash() {
  const m = location.hash.match(/^#edit=(.*)$/);
  try {
    const k = m ? JSON.parse(decodeURIComponent(m[1])) : null;
    return k && k.design && typeof k.design === 'object' && !Array.isArray(k.design) ? k : null;
  } catch (e) { return null; }
}

// A printed part's sliced G-code: uploaded (POST /api/gcode, read in memory by the server,
// kept by an id), it becomes the part as "print": {"gcode": "upload:ID"}; the print model's
// design is pinned beside it, as tippe slice shows the two.
function gcodeField(form, i, p) {
  const row = document.createElement('div');
  row.className = 'field gcode';
  row.dataset.path = `parts[${i}].print.gcode`;
  const id = `f-parts_${i}__print_gcode`;
  const lab = Object.assign(document.createElement('label'), { htmlFor: id, textContent: 'sliced G-code' });
  const file = Object.assign(document.createElement('input'), { type: 'file', id, accept: '.gcode,.gco,.g,text/x-gcode' });
  file.className = 'gcode-file';
  const status = Object.assign(document.createElement('span'), { className: 'gcode-status' });
  const g = p.print.gcode;
  status.textContent = typeof g === 'string' ? (state.gcodeNames[g] || g) : 'none: the print model';
  const msg = document.createElement('div'); msg.className = 'msg'; msg.hidden = true;
  file.addEventListener('change', async () => {
    const f = file.files[0];
    if (!f) return;
    status.textContent = `reading ${f.name}…`;
    const r = await upload('/api/gcode?name=' + encodeURIComponent(f.name), f).catch((e) => ({ ok: false, error: e.message }));
    file.value = '';
    if (!r.ok) { status.textContent = 'refused: ' + (r.json ? r.json.error : r.error || 'HTTP ' + r.status); return; }
    state.gcodeNames[r.json.gcode] = `${r.json.name} (${r.json.generator || 'unknown slicer'}, ${r.json.layers} layers)`;
    state.gcodeFiles[r.json.gcode] = r.json.name;
    // the print model's design, pinned with its zones, beside the G-code's
    if (!state.pinned && state.sweep && !state.inFlight && timer === null)
      state.pinned = { design: state.sweepDesign, sweep: state.sweep, title: `${state.shownTitle}: the print model` };
    const d2 = JSON.parse(JSON.stringify(state.design));
    d2.parts[i].print.gcode = r.json.gcode;
    editDesign(d2);
    if (state.pinned) $('pinned').hidden = false;
  });
  const remove = Object.assign(document.createElement('button'), { type: 'button', className: 'reset', textContent: '✕',
    title: 'the print model instead of the G-code', hidden: typeof g !== 'string' });
  remove.setAttribute('aria-label', remove.title);
  remove.addEventListener('click', () => {
    const d2 = JSON.parse(JSON.stringify(state.design));
    delete d2.parts[i].print.gcode;
    editDesign(d2);
  });
  row.append(lab, file, status, remove, msg);
  form.appendChild(row);
}

// A raw body (an uploaded file) to the API: its answer as api() gives it.
async function upload(path, blob) {
  const headers = { 'Content-Type': 'text/x-gcode' };
  if (token) headers['X-Tippe-Token'] = token;
  const r = await fetch(path, { method: 'POST', headers, body: blob });
  const type = r.headers.get('Content-Type') || '';
  return { ok: r.ok, status: r.status, json: type.startsWith('application/json') ? await r.json() : null };
}

// Each printed part as printed: the G-code's body beside the print model's (tippe slice's
// comparison), or the print model's alone, with the weighed mass when given.
function drawPrinted(s) {
  const box = $('printed');
  box.textContent = '';
  for (const p of s.printed_parts || []) {
    const line = document.createElement('div');
    const g = (x) => fmt(x * 1e3, 2) + ' g';
    if (p.model === 'gcode')
      line.textContent = `${p.part}: the G-code's body (${state.gcodeNames[p.gcode] || p.gcode + ', ' + (p.gcode_generator || 'unknown slicer')}) ` +
        `${g(p.printed_mass_kg)}, body A/C ${fmt(p.body_A_over_C, 5)}; the print model's ${g(p.model_mass_kg)}, ` +
        `A/C ${fmt(p.model_body_A_over_C, 5)} (the G-code ${fmt(100 * (p.printed_mass_kg / p.model_mass_kg - 1), 1)} %)` +
        (p.calibrated ? `; weighed ${g(p.measured_mass_kg)}: its lines scaled by ${fmt(p.flow_factor, 3)}` : '');
    else
      line.textContent = `${p.part}: the print model's ${g(p.printed_mass_kg)} (${p.pattern}, infill ${fmt(100 * p.infill, 1)} %` +
        (p.calibrated ? `, solved from the weighed ${g(p.measured_mass_kg)}` : '') + `), body A/C ${fmt(p.body_A_over_C, 5)}`;
    line.className = 'printed-part';
    box.appendChild(line);
  }
}

// A moving screw bought from the catalogue: its item named (catalogue_item, which tippe
// build names it by), its radius and length the item's model (the loader requires them),
// and the hole it turns in (a void cylinder of the screw's radius) at that radius too.
function catalogueField(form, i, p) {
  const row = document.createElement('div');
  row.className = 'field';
  row.dataset.path = `parts[${i}].catalogue_item`;
  const id = `f-parts_${i}__catalogue_item`;
  const lab = Object.assign(document.createElement('label'), { htmlFor: id, textContent: 'catalogue screw' });
  const sel = Object.assign(document.createElement('select'), { id });
  sel.appendChild(Object.assign(document.createElement('option'), { value: '', textContent: '(none: as modelled)' }));
  for (const it of state.catalogue)
    sel.appendChild(Object.assign(document.createElement('option'), { value: it.name,
      textContent: `${it.name} (${it.thread} x ${it.pitch_mm}, ${it.height_mm} mm; ${it.set})` }));
  sel.value = p.catalogue_item || '';
  sel.title = 'a set screw of the catalogue: tippe build names it, its thread and pitch';
  sel.addEventListener('change', () => {
    const d2 = JSON.parse(JSON.stringify(state.design));
    const screw = d2.parts[i];
    const it = state.catalogue.find((x) => x.name === sel.value);
    if (!it) { delete screw.catalogue_item; editDesign(d2); return; }
    for (const q of d2.parts)
      if (q.void && q.shape === 'cylinder' && Math.abs(q.radius_mm - screw.radius_mm) < 1e-6) q.radius_mm = it.radius_mm;
    screw.catalogue_item = it.name;
    screw.radius_mm = it.radius_mm;
    screw.height_mm = it.height_mm;
    editDesign(d2);
  });
  const msg = document.createElement('div'); msg.className = 'msg'; msg.hidden = true;
  row.append(lab, sel, msg);
  form.appendChild(row);
}

// A field's reset: back to the value of the design as opened (shown only once it differs).
function resetButton(path, label) {
  const b = document.createElement('button');
  b.type = 'button'; b.className = 'reset'; b.textContent = '↺'; b.hidden = true;
  b.title = `reset ${label} to the design's value`;
  b.setAttribute('aria-label', b.title);
  b.addEventListener('click', () => {
    const v = getPath(JSON.parse(state.original), path);
    noteEdit(null);
    setPath(state.design, path, v);
    const row = b.closest('.field');
    if (row.show) row.show(v);
    edited();
  });
  return b;
}

// A --set line on the design as edited (parts named as in the design), as the command
// applies it; 0 when a path is not one the page can follow.
function applySets(sets) {
  const d = JSON.parse(JSON.stringify(state.design));
  for (const line of sets) {
    const i = line.indexOf('=');
    if (i < 0) return 0;
    let value = line.slice(i + 1);
    try { value = JSON.parse(value); } catch (e) { /* a word: a material's name */ }
    const keys = line.slice(0, i).split('.');
    let o = d;
    for (let k = 0; k < keys.length - 1; k++) {
      if (keys[k] === 'parts' && Array.isArray(o.parts)) {
        const name = keys[++k];
        o = o.parts.find((p) => p.name === name);
        if (k === keys.length - 1) return 0;
      } else o = o[keys[k]];
      if (!o || typeof o !== 'object') return 0;
    }
    // null drops the field, as --set FIELD=null does (a weighing the change makes stale)
    if (value === null) delete o[keys[keys.length - 1]]; else o[keys[keys.length - 1]] = value;
  }
  editDesign(d);
  return 1;
}

// The section drawing of a valid design (tippe export's, /api/section), with the weight
// at the clicked Z2 or mid-travel; an older request is cancelled by a newer one.
let sectionAbort = null;
async function drawSection(design) {
  if (sectionAbort) sectionAbort.abort();
  const ctl = sectionAbort = new AbortController();
  const req = { design };
  if (state.z2 !== null) req.z2_mm = state.z2;
  let r;
  try { r = await api('/api/section', req, ctl.signal); } catch (e) { return; }
  if (ctl.signal.aborted) return;
  const img = $('section');
  if (!r.ok || !r.blob) { img.hidden = true; $('section-note').textContent = 'the section: ' + (r.json ? r.json.error : 'HTTP ' + r.status); return; }
  if (img.src) URL.revokeObjectURL(img.src);
  img.src = URL.createObjectURL(r.blob);
  img.hidden = false;
  img.dataset.z2 = req.z2_mm === undefined ? 'mid' : String(req.z2_mm);
  $('section-note').textContent = `the weight at ${req.z2_mm === undefined ? 'mid-travel' : 'Z2 = ' + req.z2_mm + ' mm'} (click the bar to move it); tippe export draws the same`;
}

// The design as edited, downloaded. A part's uploaded G-code ("upload:ID", which only
// this server knows) is named by the uploaded file's name, a file beside the saved design
// (a part's G-code is relative to its design file), so that tippe build reads it there;
// opened on the page again, the part asks for that file (the server opens no path).
function save() {
  const d = JSON.parse(JSON.stringify(state.design)), named = [];
  for (const p of d.parts || []) {
    const g = p && p.print && typeof p.print === 'object' ? p.print.gcode : null;
    if (typeof g === 'string' && g.startsWith('upload:') && state.gcodeFiles[g]) {
      p.print.gcode = state.gcodeFiles[g];
      named.push(p.print.gcode);
    }
  }
  const blob = new Blob([JSON.stringify(d, null, 2) + '\n'], { type: 'application/json' });
  const a = document.createElement('a');
  a.href = URL.createObjectURL(blob);
  a.download = stem() + '.json';
  document.body.appendChild(a); a.click(); a.remove();
  $('save-status').textContent = named.length
    ? `${a.download} names its G-code ${named.join(', ')} as a file beside it: keep them in one folder for tippe build`
    : '';
}

// The sheet's changes one can buy or set (up to three), each with a button that tries its
// --set lines on the form, as a pole's fix is tried.
function adviceList(a) {
  const ul = document.createElement('ul');
  const sets = a.to_make_it_settable || [];
  a.advice.slice(0, 3).forEach((x, k) => {
    const li = document.createElement('li');
    li.appendChild(Object.assign(document.createElement('span'), { className: 'advice-text', textContent: x }));
    if (sets[k] && sets[k].advice === x) {
      const btn = Object.assign(document.createElement('button'), { type: 'button', className: 'apply-advice', textContent: 'Try it on the form' });
      btn.title = sets[k].set.map((v) => '--set ' + v).join(' ');
      btn.addEventListener('click', () => applySets(sets[k].set));
      li.append(' ', btn);
    }
    ul.appendChild(li);
  });
  return ul;
}
