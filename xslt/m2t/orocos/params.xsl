<?xml version="1.0" encoding="UTF-8"?>
<!--
  xslt/m2t/orocos/params.xsl - public parameters of the Orocos text stage.

  Reads:   nothing.  Writes: nothing.  Errors: none.
  Params:  model-dir-from-output.
  (package-name is a parameter of xslt/m2m/20-orocos-psm.xsl: the PSM
  carries the package name.)
-->
<xsl:stylesheet version="3.0"
    xmlns:xsl="http://www.w3.org/1999/XSL/Transform"
    xmlns:xs="http://www.w3.org/2001/XMLSchema"
    exclude-result-prefixes="#all">

  <xsl:param name="model-dir-from-output" as="xs:string" select="'.'">
    <!-- directory of the model file relative to the output folder, '/'-separated; used only for relative library paths -->
  </xsl:param>
</xsl:stylesheet>
