// "Download PNG / CSV" controls for figures.

/** CSV text from a header and rows of values (numbers at full precision; null → empty). */
export function toCSV(header, rows) {
  const cell = (v) => {
    if (v === null || v === undefined) return '';
    const s = typeof v === 'number' ? String(v) : String(v);
    return /[",\n]/.test(s) ? `"${s.replace(/"/g, '""')}"` : s;
  };
  return [header, ...rows].map((r) => r.map(cell).join(',')).join('\n') + '\n';
}

function save(blob, filename) {
  const a = document.createElement('a');
  a.href = URL.createObjectURL(blob);
  a.download = filename;
  document.body.append(a);
  a.click();
  a.remove();
  setTimeout(() => URL.revokeObjectURL(a.href), 1000);
}

/** A copy of a canvas's bitmap on white (the page's canvases are transparent). */
export function onWhite(canvas) {
  const out = document.createElement('canvas');
  out.width = canvas.width;
  out.height = canvas.height;
  const ctx = out.getContext('2d');
  ctx.fillStyle = '#ffffff';
  ctx.fillRect(0, 0, out.width, out.height);
  ctx.drawImage(canvas, 0, 0);
  return out;
}

/**
 * Adds "PNG" and "CSV" buttons to `parent` (a figure or its caption): `png()` returns the
 * canvas to save, `csv()` the CSV text; files are named `<name>.png` / `<name>.csv` (`name`
 * may be a function, for names that follow the page's settings). Either may be left out. The buttons carry data-download="png" / "csv".
 */
export function downloads(parent, { name, png = null, csv = null }) {
  const nameOf = () => (typeof name === 'function' ? name() : name);
  const bar = document.createElement('span');
  bar.className = 'downloads';
  const button = (kind, label, act) => {
    const b = document.createElement('button');
    b.type = 'button';
    b.dataset.download = kind;
    b.textContent = label;
    b.title = `download the figure as ${kind.toUpperCase()}`;
    b.addEventListener('click', act);
    bar.append(b);
  };
  if (png) button('png', 'PNG', () => onWhite(png()).toBlob((blob) => save(blob, `${nameOf()}.png`), 'image/png'));
  if (csv) button('csv', 'CSV', () => save(new Blob([csv()], { type: 'text/csv' }), `${nameOf()}.csv`));
  parent.append(bar);
  return bar;
}
