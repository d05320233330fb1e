<?xml version="1.0" encoding="UTF-8"?>
<!--
  xslt/m2t/common/package-manifest.xsl - who makes a generated package and under which license.

  Reads:   nothing.  Writes: strings (package.xml lines), for every target's
           package.xml (catkin / ament / Orocos package format 3).
  Params:  package-version, maintainer-email here; maintainer-name and
           license in text.xsl (the driver passes the options
           package-version, maintainer and license of robomda; without them
           the placeholders below are written and the driver warns, PKG002).
  Errors:  none.
-->
<xsl:stylesheet version="3.0"
    xmlns:xsl="http://www.w3.org/1999/XSL/Transform"
    xmlns:xs="http://www.w3.org/2001/XMLSchema"
    xmlns:f="urn:robomda:xslt:function"
    xmlns:fp="urn:robomda:xslt:function:private"
    exclude-result-prefixes="#all">

  <xsl:param name="package-version" as="xs:string" select="''">
    <!-- the package's version (X.Y.Z); empty: 0.0.0 -->
  </xsl:param>
  <xsl:param name="maintainer-email" as="xs:string" select="''">
    <!-- the maintainer's e-mail address; empty: a placeholder -->
  </xsl:param>
  <!-- the version, description, maintainer and license lines of
       package.xml, indented by two; $description is the description line -->
  <xsl:function name="f:package-manifest-fields" as="xs:string+">
    <xsl:param name="description" as="xs:string"/>
    <xsl:sequence select="
        concat('  &lt;version&gt;', fp:manifest-text(($package-version[normalize-space(.)], '0.0.0')[1]), '&lt;/version&gt;'),
        $description,
        concat('  &lt;maintainer email=&quot;', fp:manifest-text(($maintainer-email[normalize-space(.)], 'maintainer@example.com')[1]),
               '&quot;&gt;', fp:manifest-text(($maintainer-name[normalize-space(.)], 'robomda user')[1]), '&lt;/maintainer&gt;'),
        concat('  &lt;license&gt;', fp:manifest-text(($license[normalize-space(.)], 'TODO')[1]), '&lt;/license&gt;')"/>
  </xsl:function>

  <xsl:function name="fp:manifest-text" as="xs:string">
    <xsl:param name="text" as="xs:string"/>
    <xsl:sequence select="replace(replace(replace(normalize-space($text), '&amp;', '&amp;amp;'), '&lt;', '&amp;lt;'), '&quot;', '&amp;quot;')"/>
  </xsl:function>
</xsl:stylesheet>
