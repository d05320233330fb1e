<?xml version="1.0" encoding="UTF-8"?>
<!--
  xslt/import/dialect-magicdraw.xsl - MagicDraw / Cameo quirks (XMI 2.4, 2.5).

  Reads:   the original XMI (mode mp:normalise-extra, called by the
           normalisation in xmi-common.xsl for every element with an href).
  Writes:  attribute x:referent-path on normalised elements.
  Params:  none.
  Errors:  none.

  Rules
  - References into other projects and used libraries are hrefs such as
    href="Arrowhead Core.mdzip#_19_0_3_..." whose fragment is an opaque id.
    MagicDraw puts the referenced element's qualified name beside it, in
    xmi:Extension/referenceExtension/@referentPath. The extension block is
    dropped, but that path is kept (x:referent-path) so the type gets its
    real name (last segment of the path).
  - Comments carry the text in a body attribute, not a body element
    (handled by fp:doc for every tool).
  - A connector end on a port of a part of a part carries the SysML
    NestedConnectorEnd stereotype, propertyPath as child elements
    (xmi:idref) or an id list, its last step also written as partWithPort
    (connector-ends.xsl reads every form).
  - Tool: xmi:Documentation/xmi:exporter "MagicDraw" / "Cameo" / "No Magic",
    or the magicdraw.com namespaces.
-->
<xsl:stylesheet version="3.0"
    xmlns:xsl="http://www.w3.org/1999/XSL/Transform"
    xmlns:xs="http://www.w3.org/2001/XMLSchema"
    xmlns:fp="urn:robomda:xslt:function:private"
    xmlns:mp="urn:robomda:xslt:mode:private"
    xmlns:x="urn:robomda:import:xmi"
    exclude-result-prefixes="#all">

  <xsl:template match="*[@href][*[local-name() eq 'Extension'][fp:is-xmi-ns(namespace-uri())]
                                 /referenceExtension/@referentPath]"
                mode="mp:normalise-extra" as="attribute()">
    <xsl:attribute name="x:referent-path" namespace="urn:robomda:import:xmi"
        select="(*[local-name() eq 'Extension']/referenceExtension/@referentPath)[1]"/>
  </xsl:template>

  <xsl:function name="fp:is-magicdraw" as="xs:boolean">
    <xsl:param name="doc" as="document-node()"/>
    <xsl:param name="exporter" as="xs:string"/>
    <xsl:sequence select="matches($exporter, 'magicdraw|cameo|no ?magic', 'i')
        or (not($exporter) and (some $ns in $doc/*/namespace::* satisfies contains($ns, 'magicdraw.com')))"/>
  </xsl:function>
</xsl:stylesheet>
