// Controls with live read-outs: sliders, button groups, selects, a progress bar.

/** The element with this id. */
export const $ = (id) => document.getElementById(id);

/**
 * Binds the range input `id` and its read-out `<output id="<id>-out">` (if any): sets the
 * input to `value` (the browser clamps it to min/max and snaps it to the step), shows
 * `format(v)` in the read-out and calls `onInput(v)` on every move. `parse` turns the
 * input's text into the value (default Number). Returns `{ input, value, set(v) }`; `set`
 * moves the slider without calling onInput and returns the value it took.
 */
export function slider(id, { value, format = String, onInput = null, parse = Number }) {
  const input = $(id);
  const output = $(`${id}-out`);
  if (value !== undefined && value !== null) input.value = String(value);
  const read = () => {
    const v = parse(input.value);
    if (output) output.value = format(v);
    return v;
  };
  if (onInput) input.addEventListener('input', () => onInput(read()));
  read();
  return {
    input,
    get value() { return parse(input.value); },
    set(v) {
      input.value = String(v);
      return read();
    },
  };
}

/**
 * A group of toggle buttons with ids `<prefix>-<value>` for each of `values`: the pressed
 * one has aria-pressed="true". `onChange(value)` is called on a click. Returns
 * `{ value, set(v) }` (`set` does not call onChange; an unknown value selects the first).
 */
export function choice(prefix, values, { value, onChange = null }) {
  let current = null;
  const set = (v) => {
    current = values.includes(v) ? v : values[0];
    for (const w of values) $(`${prefix}-${w}`).setAttribute('aria-pressed', String(w === current));
    return current;
  };
  for (const w of values) {
    $(`${prefix}-${w}`).addEventListener('click', () => {
      set(w);
      onChange?.(w);
    });
  }
  set(value);
  return { get value() { return current; }, set };
}

/** Binds the select `id`: `{ value, set(v) }`, `onChange(value)` on a change. */
export function select(id, { value, onChange = null }) {
  const el = $(id);
  if (value !== undefined && [...el.options].some((o) => o.value === value)) el.value = value;
  if (onChange) el.addEventListener('input', () => onChange(el.value));
  return { get value() { return el.value; }, set(v) { el.value = v; return el.value; } };
}

/**
 * A progress bar appended to `container` (a <progress> and a text read-out):
 * `set(fraction, text)`, `done(text)`; `element` is the wrapper.
 */
export function progressBar(container, { label = 'progress' } = {}) {
  const el = document.createElement('span');
  el.className = 'progress';
  el.innerHTML = `<progress max="1" value="0" aria-label="${label}"></progress> <output></output>`;
  container.append(el);
  const bar = el.querySelector('progress');
  const out = el.querySelector('output');
  return {
    element: el,
    set(fraction, text = `${Math.round(100 * fraction)} %`) {
      bar.value = Math.min(Math.max(fraction, 0), 1);
      out.value = text;
    },
    done(text = 'done') {
      bar.value = 1;
      out.value = text;
    },
  };
}
