# Music of other kinds than make_human_corpus's tune (r-music) under the same running speech
# (r-clean, gcin-voice speaker 3), at SNR 15-20 dB against the speech's active level (the mean power
# inside the sentences): piano-like struck notes and chords, a held chord pad, a sung line (one
# voice: harmonics under vowel formants, vibrato, glides, breaths), a drum kit alone. Each
# passage's music is drawn from a seed of its condition and name, so the same files come out every
# time. Needs numpy (Debian's python3-numpy).
#
#   /usr/bin/python3 bench/make_music_kinds.py HUMAN_CORPUS/r-clean OUT [--alone]
#   build/bin/align_bench OUT
#
# --alone writes each passage's music without the voice, at the level it has under it, beside the
# voice's transcript (conditions m-piano-alone ...): a recording that holds no speech, which the
# aligner is to refuse as such.
import numpy as np, json, wave, os, shutil, sys, zlib
SR=16000
def load(p):
    w=wave.open(p); return np.frombuffer(w.readframes(w.getnframes()),dtype=np.int16).astype(np.float64)/32768
def save(p,x):
    w=wave.open(p,'wb'); w.setnchannels(1); w.setsampwidth(2); w.setframerate(SR)
    w.writeframes(np.clip(np.round(x*32767),-32768,32767).astype(np.int16).tobytes()); w.close()
def speech_power(x,d):
    # the speech's active level: the mean power inside the truth's sentences
    mask=np.zeros(len(x),bool)
    for s in d['sentences']: mask[int(s['start']*SR):int(s['end']*SR)]=True
    return np.mean(x[mask]**2)
def note(n,start,length,f,amp,attack,decay,harm=6,tilt=1.0,stretch=0.0):
    # A note of harmonics (amplitudes 1/k^tilt, stretched as a piano's string stretches them),
    # with an attack and an exponential decay, added from `start` seconds.
    y=np.zeros(n); a=int(start*SR); L=min(int(length*SR),n-a)
    if L<=0: return y
    t=np.arange(L)/SR
    ph=2*np.pi*np.cumsum(np.full(L,f))/SR
    env=np.minimum(1,t/attack)*np.exp(-t*decay)*np.minimum(1,(length-t)/0.02)
    v=np.zeros(L)
    for k in range(1,harm+1):
        fk=k*(1+stretch*k*k)
        if fk*f>7500: break
        v+=np.sin(fk*ph)/k**tilt
    y[a:a+L]=amp*env*v; return y
def key(rng): return 220*2**(rng.integers(-5,7)/12)
def piano(n,rng):
    y=np.zeros(n); k=key(rng); t=0.0; beat=60/rng.uniform(70,120)
    scale=[0,2,4,5,7,9,11,12,14,16]
    while t<n/SR:
        # left hand: a chord each bar, decaying
        root=[0,5,7,9][rng.integers(0,4)]
        for s in (root,root+4 if root in(0,5,7) else root+3,root+7):
            y+=note(n,t,4*beat,k/2*2**(s/12),0.3,0.005,1.2,harm=8,tilt=1.3,stretch=0.0004)
        tt=t
        while tt<t+4*beat:
            d=beat*rng.choice([0.5,0.5,1,1,1.5,2])
            if rng.uniform()<0.8: y+=note(n,tt,d+0.6,k*2**(scale[rng.integers(0,10)]/12),0.45,0.004,rng.uniform(1.5,3.5),harm=8,tilt=1.3,stretch=0.0004)
            tt+=d
        t+=4*beat
    return y
def pad(n,rng):
    y=np.zeros(n); k=key(rng); t=0.0; bar=rng.uniform(2.0,4.0)
    chords=[[0,4,7,11],[5,9,12,16],[7,11,14,17],[9,12,16,19],[2,5,9,12]]
    while t<n/SR:
        c=chords[rng.integers(0,5)]
        for s in c:
            for det in (-0.003,0.003):
                y+=note(n,t,bar+0.6,k/2*2**(s/12)*(1+det),0.2,0.5,0.1,harm=7,tilt=1.5)
        t+=bar
    return y
def sung(n,rng):
    # a sung line: one voice, harmonics shaped by vowel formants, vibrato, legato glides, breaths
    k=key(rng)*rng.choice([1,2]); f=np.zeros(n); amp=np.zeros(n); t=0.0
    scale=[0,2,4,7,9,12,14]
    cur=k
    while t<n/SR:
        phrase=rng.uniform(2.0,4.5); end=min(t+phrase,n/SR)
        while t<end:
            d=rng.uniform(0.3,1.0); a=int(t*SR); b=min(int((t+d)*SR),n)
            new=k*2**(scale[rng.integers(0,7)]/12)
            g=min(b-a,int(0.06*SR)); f[a:a+g]=np.linspace(cur,new,g); f[a+g:b]=new; cur=new
            amp[a:b]=1.0; t+=d
        t+=rng.uniform(0.25,0.6)
    # smooth the loudness so phrases swell and breathe
    w=int(0.08*SR); amp=np.convolve(amp,np.ones(w)/w,'same')
    tt=np.arange(n)/SR
    ff=f*(1+0.015*np.sin(2*np.pi*5.5*tt))
    ph=2*np.pi*np.cumsum(ff)/SR
    formants=[(700,110),(1150,130),(2600,180),(3300,250)]
    v=np.zeros(n)
    for h in range(1,30):
        fh=h*ff; gain=np.zeros(n)
        for F,B in formants: gain+=1/(1+((fh-F)/B)**2)
        gain=(gain+0.02)/h**0.7*(fh<7500)
        v+=gain*np.sin(h*ph)
    return v*amp
def drums(n,rng):
    y=np.zeros(n); beat=60/rng.uniform(80,140); t=0.0
    while t<n/SR:
        for e in range(8):
            s=t+e*beat/2; a=int(s*SR); L=min(int(0.3*SR),n-a)
            if L<=0: continue
            tt=np.arange(L)/SR; wn=rng.standard_normal(L)
            v=0.2*np.diff(np.concatenate([[0],wn]))*np.exp(-tt/0.03)
            if e in(0,4) or (e==5 and rng.uniform()<0.3):
                v+=np.sin(2*np.pi*np.cumsum(50+80*np.exp(-tt/0.04))/SR)*np.exp(-tt/0.15)
            if e in(2,6): v+=(0.5*wn+0.3*np.sin(2*np.pi*190*tt))*np.exp(-tt/0.1)
            if e==7 and rng.uniform()<0.25: v+=0.6*np.sin(2*np.pi*np.cumsum(120+40*np.exp(-tt/0.05))/SR)*np.exp(-tt/0.2)
            y[a:a+L]+=v
        t+=4*beat
    return y
kinds={'m-piano':piano,'m-pad':pad,'m-sung':sung,'m-drums':drums}

# The music's generators are imported by make_intros.py; the corpus is written only when run.
def main():
    src, out = sys.argv[1], sys.argv[2]
    alone = sys.argv[3:] == ['--alone']
    names=sorted(f[:-4] for f in os.listdir(src) if f.endswith('.wav'))
    os.makedirs(out,exist_ok=True)
    described={'m-piano':'piano-like notes and chords','m-pad':'a sustained chord pad',
               'm-sung':'a sung line (one voice, formants, vibrato)','m-drums':'a drum kit alone'}
    suffix='-alone' if alone else ''
    with open(out+'/conditions.txt','w') as c:
        for kind,what in described.items():
            speech='no speech: the music alone at its level under' if alone else 'running speech'
            c.write(f'{kind}{suffix}\t{speech} (r-clean), {what}, SNR 15-20 dB\n')
    for kind,fn in kinds.items():
        folder=f'{out}/{kind}{suffix}'
        os.makedirs(folder,exist_ok=True)
        for nm in names:
            rng=np.random.default_rng(zlib.crc32((kind+nm).encode()))
            x=load(f'{src}/{nm}.wav'); d=json.load(open(f'{src}/{nm}.json'))
            ps=speech_power(x,d); m=fn(len(x),rng); pm=np.mean(m**2)
            snr=rng.uniform(15,20); y=(0 if alone else x)+m*np.sqrt(ps/pm/10**(snr/10))
            pk=np.max(np.abs(y));
            if pk>0.99: y*=0.99/pk
            save(f'{folder}/{nm}.wav',y)
            for ext in ('txt','json'): shutil.copy(f'{src}/{nm}.{ext}',f'{folder}/{nm}.{ext}')
        print(kind,'done',flush=True)

if __name__=='__main__': main()
