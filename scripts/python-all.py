"""Rewrites python/python/fisst/__init__.py and the __all__ of _fisst.pyi from the built
module's __all__ (run with the .venv Python from python/ after adding an export):
    cd python && ../.venv/bin/python ../scripts/python-all.py
"""
import re, fisst._fisst as m
names = sorted(m.__all__, key=lambda n: (n != "Result", n.lower()))
p='python/fisst/__init__.py'
init=open(p).read()
i=init.index("from ._fisst import")
init=init[:i]+"from ._fisst import (\n"+"".join(f"    {n},\n" for n in names)+")\n\n__all__ = [\n"+"".join(f'    "{n}",\n' for n in names)+"]\n"
open(p,'w').write(init)
p='python/fisst/_fisst.pyi'
s=open(p).read()
s=re.sub(r"__all__ = \[\n(    \"[^\"]+\",\n)+\]\n", "__all__ = [\n"+"".join(f'    "{n}",\n' for n in names)+"]\n", s)
open(p,'w').write(s)
print(len(names))
