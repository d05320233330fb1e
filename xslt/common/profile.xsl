<?xml version="1.0" encoding="UTF-8"?>
<!--
  xslt/common/profile.xsl - reading the robomda profile's stereotypes in a PIM.

  Reads:   pim:stereotype elements of urn:robomda:pim:1 (schemas/pim/1).
  Writes:  nothing (a function module for the model-to-model stages; the
           import uses f:is-robomda-profile on the XMI's stereotype
           applications).
  Params:  none.  Errors: none.  Keys: fp:stereotypes (an element's
           stereotype applications, by the element).

  The robomda profile (docs/profile.md) is recognised by its short name
  (the XML prefix, whatever URI a tool gave it) or by its namespace URI
  (f:is-robomda-profile, the one place that says so).
-->
<xsl:stylesheet version="3.0"
    xmlns:xsl="http://www.w3.org/1999/XSL/Transform"
    xmlns:xs="http://www.w3.org/2001/XMLSchema"
    xmlns:f="urn:robomda:xslt:function"
    xmlns:fp="urn:robomda:xslt:function:private"
    xmlns:pim="urn:robomda:pim:1"
    exclude-result-prefixes="#all">

  <xsl:variable name="f:profile-uri" as="xs:string" select="'http://robomda.org/profile/robomda/1'"/>

  <!-- true when a stereotype of the profile with XML prefix $prefix and
       namespace URI $uri is a robomda stereotype -->
  <xsl:function name="f:is-robomda-profile" as="xs:boolean">
    <xsl:param name="prefix" as="xs:string"/>
    <xsl:param name="uri" as="xs:string"/>
    <xsl:sequence select="lower-case($prefix) eq 'robomda' or $uri eq $f:profile-uri"/>
  </xsl:function>

  <!-- the stereotypes applied to an element, by the element: a look-up, not
       a scan of its children (an execution environment or a composite may
       hold one child per instance, and each instance asks) -->
  <xsl:key name="fp:stereotypes" match="pim:stereotype" use="generate-id(..)"/>

  <!-- the robomda stereotype $name applied to $e (the first, if applied
       twice), or the stereotype of a tool's own profile that stands for it
       (@means: RobotML «Software» for «Activity», xslt/import/dialects.xml) -->
  <xsl:function name="f:stereotype" as="element(pim:stereotype)?">
    <xsl:param name="element" as="element()?"/>
    <xsl:param name="name" as="xs:string"/>
    <xsl:sequence select="(if (empty($element)) then ()
                           else if (root($element) instance of document-node())
                           then key('fp:stereotypes', generate-id($element), root($element))
                           else $element/pim:stereotype)[(@name eq $name and f:is-robomda-profile(@profile, @profile-uri))
                                                         or @means eq $name][1]"/>
  </xsl:function>

  <!-- tag $tag of stereotype application $stereotype: of a robomda
       stereotype, the tag of that name; of a tool's stereotype that
       stands for one (@means), the tag that stands for $tag -->
  <xsl:function name="f:stereotype-tag" as="element(pim:tag)?">
    <xsl:param name="stereotype" as="element(pim:stereotype)?"/>
    <xsl:param name="tag" as="xs:string"/>
    <xsl:sequence select="(if ($stereotype/@means) then $stereotype/pim:tag[@means eq $tag]
                           else $stereotype/pim:tag[@name eq $tag])[1]"/>
  </xsl:function>

  <!-- a default value as written in a model, without one pair of enclosing
       double or single quotes ("abc" -> abc) -->
  <xsl:function name="f:unquote" as="xs:string">
    <xsl:param name="value" as="xs:string"/>
    <xsl:sequence select="if (matches($value, '^&quot;.*&quot;$|^''.*''$', 's')) then substring($value, 2, string-length($value) - 2) else $value"/>
  </xsl:function>
</xsl:stylesheet>
