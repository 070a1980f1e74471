// The page's controls. Every text that came from a file lands through textContent, never as HTML.

export function el(tag, attrs = {}, text = '') {
  const e = document.createElement(tag);
  for (const [k, v] of Object.entries(attrs)) e.setAttribute(k, String(v));
  if (text !== '') e.textContent = String(text);
  return e;
}

export function panel() {
  return document.getElementById('panel');
}

export function line(parent, label, value, cls = '') {
  const p = el('div', cls ? { class: cls } : {});
  p.append(el('span', { class: 'label' }, label + ' '), el('span', { class: 'value' }, value));
  parent.append(p);
  return p;
}

/// A slider 0..max with a play/pause button; onChange(k) on every move.
export function player(parent, max, onChange, fps = 30) {
  const box = el('div', { class: 'player' });
  const play = el('button', { id: 'play', type: 'button' }, 'play');
  const slider = el('input', { id: 'frame', type: 'range', min: 0, max, step: 1, value: 0 });
  const label = el('span', { id: 'frame-label' });
  box.append(play, slider, label);
  parent.append(box);
  let timer = null;
  const set = (k) => {
    slider.value = String(k);
    onChange(Number(slider.value));
  };
  slider.addEventListener('input', () => onChange(Number(slider.value)));
  play.addEventListener('click', () => {
    if (timer) {
      clearInterval(timer);
      timer = null;
      play.textContent = 'play';
      return;
    }
    play.textContent = 'pause';
    timer = setInterval(() => set((Number(slider.value) + 1) % (max + 1)), 1000 / fps);
  });
  return { slider, label, set };
}

/// A list of entries to choose from (a disagreement file's); the page's #k picks entry k.
export function chooser(parent, names, onChoose) {
  const select = el('select', { id: 'entry' });
  names.forEach((n, k) => select.append(el('option', { value: k }, n)));
  parent.append(select);
  select.addEventListener('change', () => {
    history.replaceState(null, '', '#' + select.value);
    onChoose(Number(select.value));
  });
  const fromHash = () => {
    const k = Number(location.hash.slice(1));
    return Number.isInteger(k) && k >= 0 && k < names.length ? k : 0;
  };
  window.addEventListener('hashchange', () => {
    select.value = String(fromHash());
    onChoose(fromHash());
  });
  select.value = String(fromHash());
  onChoose(fromHash());
  return select;
}
