<?xml version="1.0" encoding="UTF-8"?>
<!--
  xslt/common/errors.xsl - how every robomda stylesheet reports an error.

  Reads:   nothing (a function module, included by the stage stylesheets).
  Writes:  nothing.
  Params:  none.
  Errors:  f:fail raises the code it is given, in namespace urn:robomda:error;
           f:warn reports a warning and lets the run go on; f:report-error
           reports an error and lets the stage find the others, f:fail-all
           reports all of a list and stops.

  Contract with the driver (src/robomda/diagnostics.py): the error's
  description is "CODE: MESSAGE [xmi:id=ID]" (Saxon's Python API passes on
  the description only, so the code travels in it too). The driver maps ID back to the file,
  line and element of the user's XMI. ID is the xmi:id of the offending model
  element (in the PIM and PSMs, the @id / @xmi-id that element carries);
  "" when no element is at fault. Each code is declared, with its meaning, in
  the header of the stylesheet that raises it and listed in docs/errors.md.
-->
<xsl:stylesheet version="3.0"
    xmlns:xsl="http://www.w3.org/1999/XSL/Transform"
    xmlns:xs="http://www.w3.org/2001/XMLSchema"
    xmlns:f="urn:robomda:xslt:function"
    xmlns:err="urn:robomda:error"
    exclude-result-prefixes="#all">

  <!-- Raise error $code about the model element with id $id. -->
  <xsl:function name="f:fail" as="item()*">
    <!-- item()* so a call fits any context; it never returns -->
    <xsl:param name="code" as="xs:string"/>
    <xsl:param name="id" as="xs:string?"/>
    <xsl:param name="message" as="xs:string"/>
    <xsl:sequence select="error(QName('urn:robomda:error', 'err:' || $code),
                                $code || ': ' || $message || ' [xmi:id=' || string($id) || ']')"/>
  </xsl:function>

  <!-- Report error $code about the element with id $id and go on, so that
       one run reports every error of a stage: written as xsl:message
       "error: CODE: MESSAGE [xmi:id=ID]". The stage must then end with
       f:fail (the first error), which the driver reports before the
       reported ones; other engines print them. -->
  <xsl:function name="f:report-error" as="empty-sequence()">
    <xsl:param name="code" as="xs:string"/>
    <xsl:param name="id" as="xs:string?"/>
    <xsl:param name="message" as="xs:string"/>
    <xsl:message select="'error: ' || $code || ': ' || $message || ' [xmi:id=' || string($id) || ']'"/>
  </xsl:function>

  <!-- Raise every error of $errors (maps with code, id, message), in
       order: the first with f:fail, after reporting the others with
       f:report-error. Nothing when $errors is empty. -->
  <xsl:function name="f:fail-all" as="item()*">
    <!-- item()* so a call fits any context; it returns only when $errors is empty -->
    <xsl:param name="errors" as="map(*)*"/>
    <xsl:if test="exists($errors)">
      <xsl:for-each select="subsequence($errors, 2)">
        <xsl:sequence select="f:report-error(?code, ?id, ?message)"/>
      </xsl:for-each>
      <xsl:sequence select="f:fail($errors[1]?code, $errors[1]?id, $errors[1]?message)"/>
    </xsl:if>
  </xsl:function>

  <!-- The map f:fail-all takes for an error f:fail raised and xsl:catch
       caught: $description is its "CODE: message [xmi:id=ID]" -->
  <xsl:function name="f:error-map" as="map(*)">
    <xsl:param name="description" as="xs:string"/>
    <xsl:sequence select="map {
        'code': substring-before($description, ': '),
        'id': if (matches($description, '\[xmi:id=[^\]]*\]$', 's'))
              then replace($description, '^.*\[xmi:id=([^\]]*)\]$', '$1', 's') else '',
        'message': replace(substring-after($description, ': '), '\s*\[xmi:id=[^\]]*\]$', '', 's') }"/>
  </xsl:function>

  <!-- Report warning $code about the element with id $id; the run goes on.
       Written as xsl:message "warning: CODE: MESSAGE [xmi:id=ID]", which the
       driver collects and locates like an error; other engines print it. -->
  <xsl:function name="f:warn" as="empty-sequence()">
    <xsl:param name="code" as="xs:string"/>
    <xsl:param name="id" as="xs:string?"/>
    <xsl:param name="message" as="xs:string"/>
    <xsl:message select="'warning: ' || $code || ': ' || $message || ' [xmi:id=' || string($id) || ']'"/>
  </xsl:function>
</xsl:stylesheet>
