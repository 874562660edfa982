#!/usr/bin/env python3
"""Where a wasm module's code goes: function body sizes by name, from the code section and the
`name` section. Build the part, then keep its names:

    cargo build --release --target wasm32-unknown-unknown -p fisst-wasm --no-default-features --features metrics
    wasm-bindgen --target web --keep-debug --out-dir /tmp/sizes --out-name metrics \
        target/wasm32-unknown-unknown/release/fisst_wasm.wasm
    scripts/wasm-sizes.py /tmp/sizes/metrics_bg.wasm 40

prints the total code size, the sizes per crate, and the N largest functions (a name that appears
twice is a generic function instantiated twice).
"""
import sys, collections, re
def leb(b,i):
    r=0;s=0
    while True:
        x=b[i];i+=1;r|=(x&0x7f)<<s;s+=7
        if x<0x80: return r,i
def parse(path):
    b=open(path,'rb').read();i=8;imports=0;sizes=[];names={}
    while i<len(b):
        sid=b[i];i+=1;n,i=leb(b,i);end=i+n
        if sid==2:
            c,j=leb(b,i)
            for _ in range(c):
                l,j=leb(b,j);j+=l;l,j=leb(b,j);j+=l;k=b[j];j+=1
                if k==0: imports+=1; _,j=leb(b,j)
                elif k==1: j+=1; f=b[j];j+=1;_,j=leb(b,j); 
                elif k==2: f=b[j];j+=1;_,j=leb(b,j); 
                elif k==3: j+=2
                if k==1 and f&1: _,j=leb(b,j)
                if k==2 and f&1: _,j=leb(b,j)
        elif sid==10:
            c,j=leb(b,i)
            for _ in range(c):
                l,j=leb(b,j);sizes.append(l);j+=l
        elif sid==0:
            l,j=leb(b,i);nm=b[j:j+l].decode();j+=l
            if nm=='name':
                while j<end:
                    st=b[j];j+=1;sl,j=leb(b,j);se=j+sl
                    if st==1:
                        c,k=leb(b,j)
                        for _ in range(c):
                            idx,k=leb(b,k);l,k=leb(b,k);names[idx]=b[k:k+l].decode('utf8','replace');k+=l
                    j=se
        i=end
    out={}
    for n,sz in enumerate(sizes):
        out[names.get(n+imports,'?%d'%n)]=sz
    return out
a=parse(sys.argv[1])
def key(n):
    n=re.sub(r'::h[0-9a-f]{16}$','',n)
    return n
agg=collections.Counter()
for n,s in a.items():
    k=key(n)
    # crate-level bucket
    m=re.match(r'^<?&?(?:mut )?([a-z_0-9]+)::',k)
    agg[m.group(1) if m else k[:40]]+=s
print('total code',sum(a.values()))
for k,v in agg.most_common(25): print(v,k)
if len(sys.argv)>2:
    for n,s in sorted(a.items(),key=lambda x:-x[1])[:int(sys.argv[2])]: print(s,n[:160])
