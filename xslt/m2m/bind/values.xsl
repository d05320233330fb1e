<?xml version="1.0" encoding="UTF-8"?>
<!--
  xslt/m2m/bind/values.xsl - bind (xslt/m2m/bind.xsl): tagged values of robomda stereotypes and the parsing of values written in a model.

  Reads:   the PIM (urn:robomda:pim:1) and the working trees of fp:binding.
  Writes:  parts of pim:binding (schemas/pim/1/binding.xsd), or values.
  Params:  none.  Keys: those of bind.xsl.
  Provides: fp:tag, fp:first-tag, fp:conv, fp:conv-holder, fp:literal, fp:strip, fp:number,
           fp:integer, fp:quantity, fp:mebibytes, fp:boolean, fp:enum.
  Values with a dimension (period, memory, bandwidth) are read by
  fp:quantity only, through f:quantity (xslt/common/units.xsl): a number in
  the canonical unit, or a number with a unit.
  Errors:  BND010 a value that is not a number, an integer, a boolean, one of
           the allowed names, or a quantity (the message shows the accepted
           forms).
-->
<xsl:stylesheet version="3.0"
    xmlns:xsl="http://www.w3.org/1999/XSL/Transform"
    xmlns:xs="http://www.w3.org/2001/XMLSchema"
    xmlns:map="http://www.w3.org/2005/xpath-functions/map"
    xmlns:pim="urn:robomda:pim:1"
    xmlns:f="urn:robomda:xslt:function"
    xmlns:fp="urn:robomda:xslt:function:private"
    xmlns:m="urn:robomda:xslt:mode"
    xmlns:t="urn:robomda:xslt:template"
    xmlns:mp="urn:robomda:xslt:mode:private"
    xmlns:err="http://www.w3.org/2005/xqt-errors"
    exclude-result-prefixes="#all">

  <!-- ===================================================== stereotypes -->
  <!-- a tag value of stereotype $stereo on $e; enumeration literals given by
       reference resolve to their name; "Kind::LIT" / "Kind.LIT" -> "LIT" -->
  <xsl:function name="fp:tag" as="xs:string?">
    <xsl:param name="element" as="element()?"/>
    <xsl:param name="stereo" as="xs:string"/>
    <xsl:param name="tag" as="xs:string"/>
    <xsl:variable name="type" as="element()?" select="f:stereotype-tag(f:stereotype($element, $stereo), $tag)"/>
    <xsl:sequence select="if (empty($type)) then ()
        else if ($type/@ref = ('true', '1')) then string(key('fp:id', $type/@value, root($type))/@name)
        else string($type/@value)"/>
  </xsl:function>

  <xsl:function name="fp:literal" as="xs:string">
    <xsl:param name="value" as="xs:string"/>
    <xsl:sequence select="if (contains($value, ':') or contains($value, '.'))
                          then replace(normalize-space($value), '^.*(::|\.)([A-Za-z_][A-Za-z0-9_]*)$', '$2')
                          else normalize-space($value)"/>
  </xsl:function>

  <!-- first tag value found on the elements $es, with its source -->
  <xsl:function name="fp:first-tag" as="xs:string*">
    <xsl:param name="es" as="element()*"/>
    <xsl:param name="stereo" as="xs:string"/>
    <xsl:param name="tag" as="xs:string"/>
    <xsl:sequence select="(for $e in $es return fp:tag($e, $stereo, $tag))[normalize-space(.)][1]"/>
  </xsl:function>

  <!-- default value of the convention attribute $name of $e -->
  <xsl:function name="fp:conv" as="xs:string?">
    <xsl:param name="element" as="element()?"/>
    <xsl:param name="name" as="xs:string"/>
    <xsl:sequence select="($element ! fp:attributes(.))[@name eq $name][@default][1]/@default ! string(.)"/>
  </xsl:function>

  <!-- the id of the attribute holding that default value -->
  <xsl:function name="fp:conv-holder" as="xs:string">
    <xsl:param name="element" as="element()?"/>
    <xsl:param name="name" as="xs:string"/>
    <xsl:sequence select="string(($element ! fp:attributes(.))[@name eq $name][@default][1]/@id)"/>
  </xsl:function>

  <!-- ================================================= value parsing -->
  <xsl:function name="fp:strip" as="xs:string">
    <xsl:param name="value" as="xs:string"/>
    <xsl:sequence select="if (contains($value, '&quot;') or contains($value, ''''))
                          then replace(normalize-space($value), '^[&quot;'']|[&quot;'']$', '')
                          else normalize-space($value)"/>
  </xsl:function>

  <xsl:function name="fp:number" as="xs:double">
    <xsl:param name="value" as="xs:string"/>
    <xsl:param name="what" as="xs:string"/>
    <xsl:param name="id" as="xs:string?"/>
    <xsl:variable name="text" as="xs:string" select="replace(fp:strip($value), '[fFdD]$', '')"/>
    <xsl:sequence select="if ($text castable as xs:double and number($text) ge 0) then number($text)
        else f:fail('BND010', $id, $what || ': ''' || $value || ''' is not a non-negative number')"/>
  </xsl:function>

  <xsl:function name="fp:integer" as="xs:integer">
    <xsl:param name="value" as="xs:string"/>
    <xsl:param name="what" as="xs:string"/>
    <xsl:param name="id" as="xs:string?"/>
    <xsl:variable name="deployment" as="xs:double" select="fp:number($value, $what, $id)"/>
    <xsl:sequence select="if ($deployment eq floor($deployment)) then xs:integer($deployment)
        else f:fail('BND010', $id, $what || ': ''' || $value || ''' is not an integer')"/>
  </xsl:function>

  <!-- a value with dimension $dimension (f:quantity: period, memory,
       bandwidth) in its canonical unit (s, MiB, Mbit/s); BND010 shows the
       accepted forms -->
  <xsl:function name="fp:quantity" as="xs:double">
    <xsl:param name="value" as="xs:string"/>
    <xsl:param name="what" as="xs:string"/>
    <xsl:param name="dimension" as="xs:string"/>
    <xsl:param name="id" as="xs:string?"/>
    <xsl:sequence select="(f:quantity(fp:strip($value), $dimension),
        f:fail('BND010', $id, $what || ': ''' || $value || ''' is no ' || f:quantity-noun($dimension)
               || ' robomda reads: write ' || f:quantity-forms($dimension)))[1]"/>
  </xsl:function>

  <!-- a memory size (fp:quantity) in whole MiB, rounded to the nearest;
       BND010 for a size above 0 that rounds to 0 -->
  <xsl:function name="fp:mebibytes" as="xs:integer">
    <xsl:param name="value" as="xs:string"/>
    <xsl:param name="what" as="xs:string"/>
    <xsl:param name="id" as="xs:string?"/>
    <xsl:variable name="mib" as="xs:double" select="fp:quantity($value, $what, 'memory', $id)"/>
    <xsl:sequence select="if ($mib gt 0 and round($mib) eq 0)
        then f:fail('BND010', $id, $what || ': ''' || $value || ''' is less than 1 MiB: robomda counts memory in MiB; write '
                    || f:quantity-forms('memory'))
        else xs:integer(round($mib))"/>
  </xsl:function>

  <xsl:function name="fp:boolean" as="xs:boolean">
    <xsl:param name="value" as="xs:string"/>
    <xsl:param name="what" as="xs:string"/>
    <xsl:param name="id" as="xs:string?"/>
    <xsl:variable name="text" as="xs:string" select="lower-case(fp:strip($value))"/>
    <xsl:sequence select="if ($text = ('true', '1', 'yes')) then true()
        else if ($text = ('false', '0', 'no')) then false()
        else f:fail('BND010', $id, $what || ': ''' || $value || ''' is not a boolean')"/>
  </xsl:function>

  <xsl:function name="fp:enum" as="xs:string">
    <xsl:param name="value" as="xs:string"/>
    <xsl:param name="allowed" as="xs:string+"/>
    <xsl:param name="what" as="xs:string"/>
    <xsl:param name="id" as="xs:string?"/>
    <xsl:variable name="text" as="xs:string"
        select="upper-case(replace(fp:literal(fp:strip($value)), '[\s\-]', '_'))"/>
    <xsl:variable name="hit" as="xs:string?"
        select="$allowed[translate(., '_', '') eq translate($text, '_', '')][1]"/>
    <xsl:sequence select="if (exists($hit)) then $hit
        else f:fail('BND010', $id, $what || ': ''' || $value || ''' is not one of '
                    || string-join($allowed, ', '))"/>
  </xsl:function>
</xsl:stylesheet>
