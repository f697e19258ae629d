"""The body: its model (:mod:`rbcli.body.model`) and everything that builds, changes and
writes one — from a body file's YAML tree, Python data or :mod:`rbcli.parts`, with its
placements, includes, meshes, plausibility warnings and its JSON Schema. It reads files
through :mod:`rbcli.io` and computes through :mod:`rbcli.core`.
"""
