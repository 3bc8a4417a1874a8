# Recordings made on phones (issues 12 and 13), harsher and more varied than make_human_corpus's
# r-phone (pink noise at 30 dB, the telephone band, GSM 06.10): each kind is a chain a real phone
# applies to the person's running speech (r-clean, gcin-voice speaker 3), and two combine several
# on faster speech (r-fast, tempo 1.3-1.5; v-fast, another voice at 1.5-1.7):
#   narrowband codecs at low rates (Speex, Opus, G.723.1, G.726, MP3 at 16 kbit/s), an automatic
#   gain control that pumps the noise up in the pauses (sox compand), a loudspeaker phone in a
#   small room (short reverb, band-limit), babble (other passages of the same set summed: held-out
#   speech never sounds under a tuning passage) or street noise (brown and pink) at 10-20 dB,
#   packet loss concealment (20 ms frames dropped to silence or repeated).
# The truth is the source's: a codec's delay is measured against its input and taken out, so that
# the speech stays where the truth puts it. Every draw comes from a seed of the kind and passage
# name, and sox runs repeatable (-R), so the same files come out every time. Needs numpy, sox and
# ffmpeg (libspeex, libopus, libmp3lame).
#
#   /usr/bin/python3 bench/make_phone_kinds.py HUMAN_CORPUS VOICE_V_CORPUS OUT
#   build/bin/align_bench OUT
import numpy as np, json, wave, os, shutil, subprocess, sys, tempfile, zlib


def load(p):
    w = wave.open(p)
    return np.frombuffer(w.readframes(w.getnframes()), dtype=np.int16).astype(np.float64) / 32768, w.getframerate()


def save(p, x, sr):
    w = wave.open(p, 'wb'); w.setnchannels(1); w.setsampwidth(2); w.setframerate(sr)
    w.writeframes(np.clip(np.round(x * 32767), -32768, 32767).astype(np.int16).tobytes()); w.close()


def run(*cmd):
    subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)


def sox(x, sr, effects, out_sr=None):
    # x through sox's effects (and to out_sr), as float samples.
    with tempfile.TemporaryDirectory() as d:
        save(f'{d}/in.wav', x, sr)
        rate = ['rate', '-v', str(out_sr)] if out_sr and out_sr != sr else []
        run('sox', '-R', f'{d}/in.wav', '-b', '16', f'{d}/out.wav', *effects, *rate)
        return load(f'{d}/out.wav')[0]


def delay(ref, y, sr):
    # The lag (samples) of y behind ref, within 150 ms either way, from their cross-correlation.
    n = 1 << int(np.ceil(np.log2(len(ref) + len(y))))
    c = np.fft.irfft(np.fft.rfft(y, n) * np.conj(np.fft.rfft(ref, n)), n)
    m = int(0.15 * sr)
    lags = np.concatenate([np.arange(0, m + 1), np.arange(-m, 0)])
    return int(lags[np.argmax(np.concatenate([c[:m + 1], c[-m:]]))])


def codec(x, sr, args, ext, out_sr=8000):
    # x at 8 kHz (the phone band first) through ffmpeg's encoder `args` and back, its delay taken out.
    nb = sox(x, sr, ['sinc', '300-3400'], 8000)
    with tempfile.TemporaryDirectory() as d:
        save(f'{d}/in.wav', nb, 8000)
        run('ffmpeg', '-nostdin', '-y', '-i', f'{d}/in.wav', '-ac', '1', *args, f'{d}/coded.{ext}')
        run('ffmpeg', '-nostdin', '-y', '-i', f'{d}/coded.{ext}', '-ac', '1', '-ar', '8000', '-c:a', 'pcm_s16le',
            f'{d}/out.wav')
        y = load(f'{d}/out.wav')[0]
    lag = delay(nb, y, 8000)
    print(f'  {args[1]} delay {lag} samples', file=sys.stderr)
    y = y[lag:] if lag >= 0 else np.concatenate([np.zeros(-lag), y])
    y = np.concatenate([y, np.zeros(max(0, len(nb) - len(y)))])[:len(nb)]
    return (y, 8000) if out_sr == 8000 else (sox(y, 8000, [], out_sr), out_sr)


def active_power(x, sr, truth):
    mask = np.zeros(len(x), bool)
    for s in truth['sentences']: mask[int(s['start'] * sr):int(s['end'] * sr)] = True
    return np.mean(x[mask] ** 2)


def coloured(n, rng, exponent):
    # Noise whose power falls as 1/f^exponent (1 pink, 2 brown), unit power.
    f = np.fft.rfftfreq(n, 1.0)
    f[0] = f[1]
    s = (rng.standard_normal(len(f)) + 1j * rng.standard_normal(len(f))) / f ** (exponent / 2)
    y = np.fft.irfft(s, n)
    return y / np.sqrt(np.mean(y ** 2))


def add(x, noise, ps, snr_db):
    return x + noise * np.sqrt(ps / np.mean(noise ** 2) / 10 ** (snr_db / 10))


def street(x, sr, truth, rng, lo, hi):
    # traffic's rumble (brown) under a hiss (pink 10 dB below), at SNR lo-hi dB
    n = len(x)
    noise = coloured(n, rng, 2) + 0.3 * coloured(n, rng, 1)
    noise = sox(noise / 4, sr, ['highpass', '40'])
    return add(x, noise, active_power(x, sr, truth), rng.uniform(lo, hi))


def babble(x, sr, truth, rng, others, lo, hi):
    # 3-5 other passages of the same set, each at its own level and offset, summed
    n = len(x); b = np.zeros(n)
    for k in rng.choice(len(others), size=rng.integers(3, 6), replace=False):
        o, osr = load(others[k])
        o = sox(o, osr, [], sr) if osr != sr else o
        o = np.roll(np.resize(o, n), rng.integers(0, n)) * 10 ** (rng.uniform(-4, 0) / 20)
        b += o
    return add(x, b, active_power(x, sr, truth), rng.uniform(lo, hi))


def agc(x, sr):
    # A phone's automatic gain control: fast attack, slow release, quiet input lifted up to 30 dB,
    # so that in each pause the noise swells as the gain climbs back.
    x = x * np.sqrt(10 ** (-20 / 10) / np.mean(x[np.abs(x) > 0.01] ** 2))
    return sox(x, sr, ['compand', '0.005,0.8', '6:-70,-70,-60,-30,-20,-12,0,-6', '0', '-30', '0.02'])


def packet_loss(x, sr, rng, lo, hi):
    # 20 ms frames lost in bursts of 1-3 (a share lo-hi of frames), each either left silent or filled
    # with the frame before it (a concealment that repeats), faded over 2 ms at its edges.
    f = int(0.02 * sr); y = x.copy(); share = rng.uniform(lo, hi)
    i = 1
    while i < len(x) // f:
        if rng.uniform() < share / 2:
            burst = rng.integers(1, 4); repeat = rng.uniform() < 0.5
            for j in range(i, min(i + burst, len(x) // f)):
                y[j * f:(j + 1) * f] = y[(j - 1) * f:j * f] if repeat else 0
            i += burst + 1
        else:
            i += 1
    g = int(0.002 * sr)
    edge = np.convolve(np.abs(y - x) > 0, np.ones(2 * g), 'same') > 0
    smooth = np.convolve(y, np.ones(g) / g, 'same')
    return np.where(edge, smooth, y)


def speakerphone(x, sr, truth, rng, others):
    # a phone on the table: its small speaker-side band (250-3800 Hz), a small room's short reverb,
    # pink room noise at 20-25 dB, the telephone band and GSM
    y = sox(x, sr, ['sinc', '250-3800', 'reverb', str(rng.integers(30, 60)), '50', str(rng.integers(15, 40)),
                    'gain', '-n', '-3'])[:len(x)]
    y = add(y, coloured(len(y), rng, 1), active_power(y, sr, truth), rng.uniform(20, 25))
    return codec(y, sr, ['-c:a', 'libgsm'], 'gsm')


kinds = {
    # name: (source, what, chain(x, sr, truth, rng, others) -> (y, sr))
    'p-speex8': ('r-clean', 'Speex narrowband at 8 kbit/s, pink noise at SNR 30 dB',
                 lambda x, sr, t, r, o: codec(add(x, coloured(len(x), r, 1), active_power(x, sr, t), 30), sr,
                                               ['-c:a', 'libspeex', '-b:a', '8k'], 'ogg')),
    'p-opus6': ('r-clean', 'Opus narrowband at 6 kbit/s, pink noise at SNR 30 dB',
                lambda x, sr, t, r, o: codec(add(x, coloured(len(x), r, 1), active_power(x, sr, t), 30), sr,
                                              ['-c:a', 'libopus', '-b:a', '6k', '-application', 'voip'], 'ogg')),
    'p-opus12': ('r-clean', 'Opus narrowband at 12 kbit/s, pink noise at SNR 30 dB',
                 lambda x, sr, t, r, o: codec(add(x, coloured(len(x), r, 1), active_power(x, sr, t), 30), sr,
                                               ['-c:a', 'libopus', '-b:a', '12k', '-application', 'voip'], 'ogg')),
    'p-g723': ('r-clean', 'G.723.1 at 6.3 kbit/s, pink noise at SNR 30 dB',
               lambda x, sr, t, r, o: codec(add(x, coloured(len(x), r, 1), active_power(x, sr, t), 30), sr,
                                             ['-c:a', 'g723_1', '-b:a', '6300'], 'wav')),
    'p-g726': ('r-clean', 'G.726 ADPCM at 16 kbit/s, pink noise at SNR 30 dB',
               lambda x, sr, t, r, o: codec(add(x, coloured(len(x), r, 1), active_power(x, sr, t), 30), sr,
                                             ['-c:a', 'g726', '-b:a', '16k'], 'wav')),
    'p-mp3': ('r-clean', 'MP3 (LAME) mono at 16 kbit/s, pink noise at SNR 30 dB',
              lambda x, sr, t, r, o: codec(add(x, coloured(len(x), r, 1), active_power(x, sr, t), 30), sr,
                                            ['-c:a', 'libmp3lame', '-b:a', '16k'], 'mp3', 16000)),
    'p-agc': ('r-clean', 'pink noise at SNR 20-25 dB, then an AGC that lifts the noise in pauses (sox compand)',
              lambda x, sr, t, r, o: (agc(add(x, coloured(len(x), r, 1), active_power(x, sr, t), r.uniform(20, 25)),
                                          sr), sr)),
    'p-speaker': ('r-clean', 'loudspeaker phone in a small room: 250-3800 Hz, short reverb, pink noise '
                  'at SNR 20-25 dB, telephone band, GSM 06.10', speakerphone),
    'p-babble': ('r-clean', 'babble (3-5 other passages of the same set) at SNR 10-20 dB',
                 lambda x, sr, t, r, o: (babble(x, sr, t, r, o, 10, 20), sr)),
    'p-street': ('r-clean', 'street noise (brown and pink) at SNR 10-20 dB',
                 lambda x, sr, t, r, o: (street(x, sr, t, r, 10, 20), sr)),
    'p-loss': ('r-clean', 'GSM 06.10, 3-8% of 20 ms frames lost in bursts (silent or repeated)',
               lambda x, sr, t, r, o: (lambda y: (packet_loss(y[0], y[1], r, 0.03, 0.08), y[1]))(
                   codec(add(x, coloured(len(x), r, 1), active_power(x, sr, t), 30), sr, ['-c:a', 'libgsm'], 'gsm'))),
    'p-fast-combo': ('r-fast', 'tempo 1.3-1.5: street noise at SNR 15-20 dB, AGC, Opus narrowband 8 kbit/s',
                     lambda x, sr, t, r, o: codec(agc(street(x, sr, t, r, 15, 20), sr), sr,
                                                   ['-c:a', 'libopus', '-b:a', '8k', '-application', 'voip'], 'ogg')),
    'p-vfast-combo': ('v-fast', 'another voice at tempo 1.5-1.7: babble at SNR 15-20 dB, AGC, GSM 06.10, '
                      '2-4% of frames lost',
                      lambda x, sr, t, r, o: (lambda y: (packet_loss(y[0], y[1], r, 0.02, 0.04), y[1]))(
                          codec(agc(babble(x, sr, t, r, o, 15, 20), sr), sr, ['-c:a', 'libgsm'], 'gsm'))),
}



def main():
    # short_kinds_bench.py imports the kinds' chains; the corpus is made only when run.
    human, voice, out = sys.argv[1:4]
    only = set(sys.argv[4].split(',')) if len(sys.argv) > 4 else None
    os.makedirs(out, exist_ok=True)
    with open(out + '/conditions.txt', 'w') as c:
        for kind, (source, what, _) in kinds.items():
            if only is None or kind in only: c.write(f'{kind}\t{source}: {what}\n')
    for kind, (source, what, chain) in kinds.items():
        if only is not None and kind not in only: continue
        src = f'{human if source.startswith("r-") else voice}/{source}'
        names = sorted(f[:-4] for f in os.listdir(src) if f.endswith('.wav'))
        folder = f'{out}/{kind}'
        os.makedirs(folder, exist_ok=True)
        for nm in names:
            rng = np.random.default_rng(zlib.crc32((kind + nm).encode()))
            same_set = [f'{src}/{o}.wav' for o in names if o != nm and o.split('-')[0] == nm.split('-')[0]]
            x, sr = load(f'{src}/{nm}.wav'); d = json.load(open(f'{src}/{nm}.json'))
            y, ysr = chain(x, sr, d, rng, same_set)
            pk = np.max(np.abs(y))
            if pk > 0.99: y *= 0.99 / pk
            save(f'{folder}/{nm}.wav', y, ysr)
            for ext in ('txt', 'json'): shutil.copy(f'{src}/{nm}.{ext}', f'{folder}/{nm}.{ext}')
        print(kind, 'done', flush=True)


if __name__ == '__main__':
    main()
