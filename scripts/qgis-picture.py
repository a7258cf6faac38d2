#!/usr/bin/python3
"""Draws what a QGIS user sees after `flood check --findings`: the dataset, and over it the two
layers Flood wrote (a point per finding labelled with its feature's name, the culprit edges in
red), rendered by QGIS itself (PyQGIS, no window) so the tutorial's picture is QGIS's own.

    scripts/qgis-picture.py DATA FINDINGS.gpkg OUT.png [WIDTHxHEIGHT]

Needs Debian's python3-qgis and qgis-providers (scripts/tutorial-images.sh skips the picture
without them). Run it with /usr/bin/python3: the module lives in Debian's dist-packages.
"""
import os
import sys

os.environ.setdefault("QT_QPA_PLATFORM", "offscreen")  # no display needed

from qgis.core import (  # noqa: E402
    QgsApplication,
    QgsMapRendererParallelJob,
    QgsMapSettings,
    QgsPalLayerSettings,
    QgsRectangle,
    QgsTextBufferSettings,
    QgsTextFormat,
    QgsVectorLayer,
    QgsVectorLayerSimpleLabeling,
)
from qgis.PyQt.QtCore import QSize  # noqa: E402
from qgis.PyQt.QtGui import QColor, QFont  # noqa: E402


def layer(uri, name):
    found = QgsVectorLayer(uri, name, "ogr")
    if not found.isValid():
        sys.exit(f"qgis-picture: QGIS cannot open {uri}")
    return found


def main():
    if len(sys.argv) not in (4, 5):
        sys.exit(__doc__.strip().splitlines()[3].strip())
    data, findings, out = sys.argv[1:4]
    width, height = (int(v) for v in (sys.argv[4] if len(sys.argv) == 5 else "900x600").split("x"))

    QgsApplication.setPrefixPath("/usr", True)
    app = QgsApplication([], False)
    app.initQgis()

    faces = layer(data, "data")
    faces.renderer().symbol().setColor(QColor(120, 160, 210, 90))
    faces.renderer().symbol().symbolLayer(0).setStrokeColor(QColor(40, 70, 120))
    edges = layer(f"{findings}|layername=finding_edges", "finding_edges")
    edges.renderer().symbol().setColor(QColor(215, 25, 28))
    edges.renderer().symbol().setWidth(1.2)
    points = layer(f"{findings}|layername=findings", "findings")
    points.renderer().symbol().setColor(QColor(215, 25, 28))
    points.renderer().symbol().setSize(3.5)

    # Each point says which feature it belongs to, as QGIS's labels would once switched on.
    label = QgsPalLayerSettings()
    label.fieldName = "coalesce(name, 'feature ' || fid) || ': ring ' || ring || ' vertex ' || vertex"
    label.isExpression = True
    text = QgsTextFormat()
    text.setFont(QFont("DejaVu Sans"))
    text.setSize(9)
    buffer = QgsTextBufferSettings()
    buffer.setEnabled(True)
    buffer.setSize(1)
    text.setBuffer(buffer)
    label.setFormat(text)
    points.setLabeling(QgsVectorLayerSimpleLabeling(label))
    points.setLabelsEnabled(True)

    settings = QgsMapSettings()
    settings.setLayers([points, edges, faces])  # top first
    settings.setDestinationCrs(faces.crs())
    extent = QgsRectangle(faces.extent())
    extent.combineExtentWith(points.extent())
    extent.scale(1.1)
    settings.setExtent(extent)
    settings.setOutputSize(QSize(width, height))
    settings.setBackgroundColor(QColor(255, 255, 255))

    job = QgsMapRendererParallelJob(settings)
    job.start()
    job.waitForFinished()
    image = job.renderedImage()
    tmp = out + ".tmp.png"
    if not image.save(tmp, "PNG"):
        sys.exit(f"qgis-picture: cannot write {out}")
    os.replace(tmp, out)  # atomically: a failed run leaves the old picture
    # Exit at once: Python tearing the layers down after QGIS has gone segfaults (3.22).
    os._exit(0)


if __name__ == "__main__":
    main()
