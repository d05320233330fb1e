<?xml version="1.0" encoding="UTF-8"?>
<!--
  xslt/import/dialect-other.xsl - StarUML and Visual Paradigm quirks.

  Reads:   the original XMI (tool signatures).
  Writes:  nothing itself; functions used by import.xsl.
  Params:  none.
  Errors:  none.

  Rules
  - StarUML (XMI 2.1, UML http://schema.omg.org/spec/UML/2.0) writes the
    types it knows (int, string, void ...) as uml:DataType elements at the
    end of the model; a DataType without attributes whose name is in the
    primitive table gets @primitive (fp:is-primitive-like, xmi-common.xsl).
    Associations are ownedMember of a class; they carry no PIM content.
    Its ids are base64 strings (AAAAAAF...).
  - Visual Paradigm: recognised by its exporter / namespace only; it writes
    standard XMI 2.1 otherwise.
-->
<xsl:stylesheet version="3.0"
    xmlns:xsl="http://www.w3.org/1999/XSL/Transform"
    xmlns:xs="http://www.w3.org/2001/XMLSchema"
    xmlns:fp="urn:robomda:xslt:function:private"
    exclude-result-prefixes="#all">

  <!-- $marked-id: as for fp:is-ea (dialect-ea.xsl); the ids are scanned
       only when some looks like a StarUML one -->
  <xsl:function name="fp:is-staruml" as="xs:boolean">
    <xsl:param name="doc" as="document-node()"/>
    <xsl:param name="exporter" as="xs:string"/>
    <xsl:param name="marked-id" as="xs:string?"/>
    <xsl:sequence select="contains(lower-case($exporter), 'staruml')
        or (not($exporter) and exists($marked-id)
            and exists(($doc/*//@*:id[starts-with(., 'AAAAAA')][matches(., '^AAAAAA[A-Za-z0-9+/]{10,}=*$')])[1]))"/>
  </xsl:function>

  <xsl:function name="fp:is-visual-paradigm" as="xs:boolean">
    <xsl:param name="doc" as="document-node()"/>
    <xsl:param name="exporter" as="xs:string"/>
    <xsl:sequence select="matches($exporter, 'visual ?paradigm', 'i')
        or (not($exporter) and (some $ns in $doc/*/namespace::* satisfies contains(lower-case($ns), 'visual-paradigm')))"/>
  </xsl:function>
</xsl:stylesheet>
