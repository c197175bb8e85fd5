// ctest studio_part_editor: the fuzzy-value arithmetic of the studio's part editor
// (web/modules/part_editor.js) in Node, without a browser: each form to JSON and back, the core's
// midpoint, a value moved with its shape kept, a value converted between forms keeping its
// support and core, what stops a value from being sent, the text of values, and α-cuts (the
// surface view's control nets).
import assert from 'node:assert/strict';
import {
  PART_VALUES, alphaCut, convertedTo, coreMidpoint, disorder, fromJson, fuzzyText, movedTo, toJson, valueAt,
} from '../../web/modules/part_editor.js';

const close = (a, b) => assert.ok(Math.abs(a - b) < 1e-12, `${a} != ${b}`);

// The fourteen values, each a path into {params, transform}.
assert.equal(PART_VALUES.length, 14);
const part = { params: { a1: 2, kv: { tri: [0, 0.1, 0.2] } }, transform: { translate: [1, 2, 3], rotate: { deg: 30 } } };
assert.equal(valueAt(part, 'params.a1'), 2);
assert.equal(valueAt(part, 'transform.translate.2'), 3);
assert.equal(valueAt(part, 'transform.rotate.deg'), 30);
assert.equal(valueAt(part, 'transform.scale'), undefined);

// Every form to the editor's terms and back, unchanged.
for (const v of [1.5, { tri: [1, 2, 4] }, { trap: [0, 1, 2, 3] }, { about: 3, spread: 0.5 }, { points: [[0, 0], [1, 1], [2, 0.5], [3, 0]] }])
  assert.deepEqual(toJson(fromJson(v)), v);
assert.throws(() => fromJson({ gauss: 1 }));

// The core's midpoint of each form.
close(coreMidpoint(fromJson(2)), 2);
close(coreMidpoint(fromJson({ tri: [1, 2, 4] })), 2);
close(coreMidpoint(fromJson({ trap: [0, 1, 2, 3] })), 1.5);
close(coreMidpoint(fromJson({ about: 3, spread: 1 })), 3);
close(coreMidpoint(fromJson({ points: [[0, 0], [1, 1], [2, 1], [3, 0]] })), 1.5);

// Moving keeps the shape: every point shifts by the same amount.
assert.deepEqual(toJson(movedTo(fromJson({ trap: [0, 1, 2, 3] }), 2.5)), { trap: [1, 2, 3, 4] });
assert.deepEqual(toJson(movedTo(fromJson({ about: 3, spread: 1 }), 5)), { about: 5, spread: 1 });
assert.deepEqual(toJson(movedTo(fromJson({ points: [[0, 0], [1, 1], [2, 0]] }), 2)), { points: [[1, 0], [2, 1], [3, 0]] });
assert.deepEqual(toJson(movedTo(fromJson(2), 3)), 3);

// Converting keeps support and core; a crisp value made fuzzy gets a tenth of itself (at least
// 0.1) each side, as "about N" does; back to crisp is the core's midpoint.
assert.deepEqual(toJson(convertedTo(fromJson({ trap: [0, 1, 2, 4] }), 'tri')), { tri: [0, 1.5, 4] });
assert.deepEqual(toJson(convertedTo(fromJson({ tri: [0, 1, 4] }), 'trap')), { trap: [0, 1, 1, 4] });
assert.deepEqual(toJson(convertedTo(fromJson({ tri: [0, 1, 4] }), 'about')), { about: 1, spread: 3 });
assert.deepEqual(toJson(convertedTo(fromJson({ tri: [0, 1, 4] }), 'crisp')), 1);
assert.deepEqual(toJson(convertedTo(fromJson(20), 'tri')), { tri: [18, 20, 22] });
assert.deepEqual(toJson(convertedTo(fromJson(0), 'about')), { about: 0, spread: 0.1 });

// What the editor will not send while it is being typed.
assert.equal(disorder(fromJson({ tri: [1, 2, 3] })), '');
assert.equal(disorder(fromJson({ tri: [1, 3, 2] })), 'points in increasing order');
assert.equal(disorder(fromJson({ about: 1, spread: -1 })), 'a spread of at least 0');
assert.equal(disorder({ form: 'crisp', xs: [NaN] }), 'a number');
assert.equal(disorder({ form: 'trap', xs: [0, NaN, 1, 2] }), 'numbers');
assert.equal(disorder(fromJson({ points: [[0, 0], [1, 1]] })), '');

// Values as text, to four significant digits.
assert.equal(fuzzyText(0.078539816), '0.07854');
assert.equal(fuzzyText({ trap: [0, 0.0785398, 0.19634954, 0.314159] }), 'trap(0, 0.07854, 0.1963, 0.3142)');
assert.equal(fuzzyText({ about: 3, spread: 0.5 }), 'about 3 ± 0.5');
assert.equal(fuzzyText(undefined), '—');

console.log('part editor values: ok');

// α-cuts: the triangle's [l + α(m − l), r − α(r − m)]; a crisp value is itself; points linear.
assert.deepEqual(alphaCut(fromJson({ tri: [-0.5, 0, 0.5] }), 0.5), [-0.25, 0.25]);
assert.deepEqual(alphaCut(fromJson({ trap: [0, 1, 2, 4] }), 0), [0, 4]);
assert.deepEqual(alphaCut(fromJson({ trap: [0, 1, 2, 4] }), 1), [1, 2]);
assert.deepEqual(alphaCut(fromJson({ about: 2, spread: 1 }), 0.5), [1.5, 2.5]);
assert.deepEqual(alphaCut(fromJson(3), 0.7), [3, 3]);
assert.deepEqual(alphaCut(fromJson({ points: [[0, 0], [1, 1], [3, 0]] }), 0.5), [0.5, 2]);
console.log('alpha cuts: ok');
