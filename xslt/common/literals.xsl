<?xml version="1.0" encoding="UTF-8"?>
<!--
  xslt/common/literals.xsl - string literals of the languages robomda
  writes, for any stage that writes them (the Orocos PSM, every text stage
  through xslt/m2t/common/text.xsl).

  Reads:   nothing.  Writes: strings.  Params: none.  Errors: none.
    fp:cpp-string($s)  a C++ / Lua / .ops double-quoted string literal
    fp:xml-text($s)    $s escaped for XML text and attribute content
-->
<xsl:stylesheet version="3.0"
    xmlns:xsl="http://www.w3.org/1999/XSL/Transform"
    xmlns:xs="http://www.w3.org/2001/XMLSchema"
    xmlns:fp="urn:robomda:xslt:function:private"
    exclude-result-prefixes="#all">

  <xsl:function name="fp:cpp-string" as="xs:string">
    <xsl:param name="s" as="xs:string?"/>
    <xsl:sequence select="concat('&quot;', (if (contains($s, '\') or contains($s, '&quot;') or contains($s, '&#10;'))
                                       then replace(replace(replace(string($s), '\\', '\\\\'), '&quot;', '\\&quot;'), '&#10;', '\\n')
                                       else string($s)), '&quot;')"/>
  </xsl:function>

  <xsl:function name="fp:xml-text" as="xs:string">
    <xsl:param name="s" as="xs:string?"/>
    <xsl:sequence select="if (contains($s, '&amp;') or contains($s, '&lt;') or contains($s, '&gt;') or contains($s, '&quot;'))
                          then replace(replace(replace(replace(string($s), '&amp;', '&amp;amp;'), '&lt;', '&amp;lt;'), '&gt;', '&amp;gt;'), '&quot;', '&amp;quot;')
                          else string($s)"/>
  </xsl:function>
</xsl:stylesheet>
