<?xml version="1.0" encoding="UTF-8"?>
<ColorCorrection id="sh020" xmlns="urn:ASC:CDL:v1.01">
  <SOPNode><Slope>0.95 1.0 1.0</Slope><Offset>-0.02 0.0 0.0</Offset><Power>1.0 1.0 1.1</Power></SOPNode>
  <SatNode><Saturation>1.1</Saturation></SatNode>
</ColorCorrection>
