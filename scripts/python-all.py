"""Rewrites python/python/fisst/__init__.py and the __all__ of _fisst.pyi from the built
module's __all__ (run with the .venv Python from python/ after adding an export):
    cd python && ../.venv/bin/python ../scripts/python-all.py
"""
import re, fisst._fisst as m
# private helpers (`_campaign_…`, used by fisst.campaign) stay out of the public names
names = sorted((n for n in m.__all__ if not (n.startswith("_") and not n.startswith("__"))), key=lambda n: (n != "Result", n.lower()))
p='python/fisst/__init__.py'
init=open(p).read()
i=init.index("from ._fisst import")
init=init[:i]+"from ._fisst import (\n"+"".join(f"    {n},\n" for n in names)+")\n\n__all__ = [\n"+"".join(f'    "{n}",\n' for n in names)+"]\n"
open(p,'w').write(init)
p='python/fisst/_fisst.pyi'
s=open(p).read()
# the stub's __all__ is the compiled module's, private helpers included
every = names + sorted(n for n in m.__all__ if n not in names)
s=re.sub(r"__all__ = \[\n(    \"[^\"]+\",\n)+\]\n", "__all__ = [\n"+"".join(f'    "{n}",\n' for n in every)+"]\n", s)
open(p,'w').write(s)
print(len(names))
