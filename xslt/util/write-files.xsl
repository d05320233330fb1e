<?xml version="1.0" encoding="UTF-8"?>
<!--
  xslt/util/write-files.xsl - write a robomda file set to disk, without Python.

  Reads:   a file set (urn:robomda:fileset:1, schemas/fileset/1/fileset.xsd).
  Writes:  one text file per fs:file, at its @path relative to the base output
           URI (Saxon: -o:OUT/files.log or the API's base output URI); the
           principal result is a short list of the paths written.
  Params:  none.
  Errors:  none of its own. Unlike the Python driver, this writer does not
           protect files a user edited: files with mode="user" are written
           under PATH.robomda-new, so nothing a user owns is overwritten.

  Usable alone (on the output of a chain's text step) or imported by
  run-pipeline.xsl.
-->
<xsl:stylesheet version="3.0"
    xmlns:xsl="http://www.w3.org/1999/XSL/Transform"
    xmlns:xs="http://www.w3.org/2001/XMLSchema"
    xmlns:fs="urn:robomda:fileset:1"
    xmlns:m="urn:robomda:xslt:mode"
    xmlns:f="urn:robomda:xslt:function"
    exclude-result-prefixes="#all">

  <xsl:output method="text" encoding="UTF-8"/>
  <xsl:mode name="m:write-files" on-no-match="shallow-skip"/>

  <xsl:template match="/" as="xs:string*">
    <xsl:apply-templates select="fs:files" mode="m:write-files"/>
    <xsl:sequence select="fs:files/fs:file ! (f:written-path(.) || '&#10;')"/>
  </xsl:template>

  <!-- where a file of the set is written: user files go beside, as PATH.robomda-new -->
  <xsl:function name="f:written-path" as="xs:string">
    <xsl:param name="file" as="element(fs:file)"/>
    <xsl:sequence select="if ($file/@mode = 'user') then $file/@path || '.robomda-new' else string($file/@path)"/>
  </xsl:function>

  <xsl:template match="fs:files" mode="m:write-files" as="empty-sequence()">
    <xsl:apply-templates select="fs:file" mode="m:write-files"/>
  </xsl:template>

  <xsl:template match="fs:file" mode="m:write-files" as="empty-sequence()">
    <xsl:result-document href="{f:written-path(.)}" method="text" encoding="UTF-8">
      <xsl:value-of select="."/>
    </xsl:result-document>
  </xsl:template>
</xsl:stylesheet>
