# Recordings as people have them (issue 13): a podcast's, a video's or an audio book's file opens
# with music, a jingle or an intro of 3-40 s, and may end with music too, the voice coming in after
# it. Each passage of the given conditions (r-clean, h-clean, espeak-ng clean ...) is written with
# make_music_kinds.py's music before it and, for about half of them, after it, the truth shifted by
# the intro's length; tuning and held-out passages keep their names and sets.
#
#   /usr/bin/python3 bench/make_intros.py OUT CORPUS/CONDITION ...
#   build/bin/align_bench OUT
#
# Kinds (condition SOURCE-KIND, e.g. r-clean-piano): piano, pad, sung, drums (3-40 s of the music
# alone, then the voice), jingle (3-8 s of piano and drums), bed (a pad or piano 3-40 s that plays
# on under the voice's first 2-5 s, fading out). The music stands 0-6 dB under the speech's active
# level and ends with a 0.3-1.0 s fade just before the passage (the passage's own lead-in silence
# follows it). Under the music lies white noise at the level of the passage's lead-in, so that a
# noisy recording's noise runs on through its intro. Outros: 3-20 s of the same music from 0.2-1.0 s
# after the passage. Deterministic: each file's draws come from a seed of its condition and name.
import json, os, sys, zlib
import numpy as np
from make_music_kinds import SR, load, save, speech_power, piano, pad, sung, drums

def jingle(n, rng):
    return piano(n, rng) + 0.5 * drums(n, rng)

def fade(n, seconds_in, seconds_out):
    g = np.ones(n); a = min(n, int(seconds_in * SR)); b = min(n, int(seconds_out * SR))
    if a: g[:a] = np.linspace(0, 1, a)
    if b: g[n - b:] *= np.linspace(1, 0, b)
    return g

def music(fn, seconds, level, rng):
    n = int(seconds * SR); m = fn(n, rng)
    return m * np.sqrt(level / np.mean(m ** 2))

kinds = {'piano': (piano, (3, 40)), 'pad': (pad, (3, 40)), 'sung': (sung, (3, 40)),
         'drums': (drums, (3, 40)), 'jingle': (jingle, (3, 8)), 'bed': (None, (3, 40))}

def make(x, d, kind, rng):
    fn, (lo, hi) = kinds[kind]
    if fn is None: fn = [pad, piano][rng.integers(0, 2)]
    ps = speech_power(x, d)
    level = ps / 10 ** (rng.uniform(0, 6) / 10)
    lead = x[:max(1, int((d['sentences'][0]['start'] - 0.05) * SR))]
    floor = np.sqrt(np.mean(lead ** 2))
    intro_s = round(rng.uniform(lo, hi), 3)
    head = int(intro_s * SR)
    if kind == 'bed':
        first = int(d['sentences'][0]['start'] * SR); under = int(rng.uniform(2, 5) * SR)
        m = music(fn, (head + first + under) / SR, level, rng)
        m[head + first:] *= np.linspace(1, 0, len(m) - head - first)
        m *= fade(len(m), 0.5, 0)
        y = np.concatenate([m[:head], x]); y[head:head + len(m) - head] += m[head:]
    else:
        m = music(fn, intro_s, level, rng) * fade(head, 0.05 if kind != 'pad' else 1.0, rng.uniform(0.3, 1.0))
        y = np.concatenate([m, x])
    y[:head] += floor * rng.standard_normal(head)
    outro_s = 0.0
    if rng.uniform() < 0.5:
        gap = int(rng.uniform(0.2, 1.0) * SR); outro_s = round(rng.uniform(3, 20), 3)
        o = music(fn, outro_s, level, rng) * fade(int(outro_s * SR), 0.05, 1.0)
        tail = np.concatenate([np.zeros(gap), o]); tail += floor * rng.standard_normal(len(tail))
        y = np.concatenate([y, tail])
    pk = np.max(np.abs(y))
    if pk > 0.99: y *= 0.99 / pk
    shift = head / SR
    d = json.loads(json.dumps(d))
    for item in d['sentences'] + d['syllables']:
        item['start'] = round(item['start'] + shift, 5); item['end'] = round(item['end'] + shift, 5)
    d['duration'] = round(len(y) / SR, 5)
    d['intro_s'] = shift; d['outro_s'] = outro_s
    return y, d

def main():
    out, sources = sys.argv[1], sys.argv[2:]
    os.makedirs(out, exist_ok=True)
    with open(out + '/conditions.txt', 'w') as c:
        for src in sources:
            base = os.path.basename(src.rstrip('/'))
            for kind in kinds:
                c.write(f'{base}-{kind}\t{base} after {kind} music (intro {kinds[kind][1][0]}-{kinds[kind][1][1]} s), '
                        f'about half with an outro\n')
    for src in sources:
        base = os.path.basename(src.rstrip('/'))
        names = sorted(f[:-4] for f in os.listdir(src) if f.endswith('.wav'))
        for kind in kinds:
            cond = f'{base}-{kind}'; folder = f'{out}/{cond}'
            os.makedirs(folder, exist_ok=True)
            for nm in names:
                rng = np.random.default_rng(zlib.crc32((cond + nm).encode()))
                x = load(f'{src}/{nm}.wav'); d = json.load(open(f'{src}/{nm}.json'))
                y, d = make(x, d, kind, rng)
                save(f'{folder}/{nm}.wav', y)
                json.dump(d, open(f'{folder}/{nm}.json', 'w'), ensure_ascii=False)
                with open(f'{src}/{nm}.txt') as t, open(f'{folder}/{nm}.txt', 'w') as o: o.write(t.read())
            print(cond, 'done', flush=True)

if __name__ == '__main__': main()
