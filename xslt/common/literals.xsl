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
    <xsl:param name="text" as="xs:string?"/>
    <xsl:sequence select="concat('&quot;', (if (contains($text, '\') or contains($text, '&quot;') or contains($text, '&#10;'))
                                       then replace(replace(replace(string($text), '\\', '\\\\'), '&quot;', '\\&quot;'), '&#10;', '\\n')
                                       else string($text)), '&quot;')"/>
  </xsl:function>

  <xsl:function name="fp:xml-text" as="xs:string">
    <xsl:param name="text" as="xs:string?"/>
    <xsl:sequence select="if (contains($text, '&amp;') or contains($text, '&lt;') or contains($text, '&gt;') or contains($text, '&quot;'))
                          then replace(replace(replace(replace(string($text), '&amp;', '&amp;amp;'), '&lt;', '&amp;lt;'), '&gt;', '&amp;gt;'), '&quot;', '&amp;quot;')
                          else string($text)"/>
  </xsl:function>
</xsl:stylesheet>
