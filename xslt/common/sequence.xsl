<?xml version="1.0" encoding="UTF-8"?>
<!--
  xslt/common/sequence.xsl - the deployment sequence (seed 002), for any
  stage that orders instances by it: the Orocos PSM (pim:instance) and the
  ROS 2 launch files (r:instance), both of which carry the binding's
  @start-order.

  Reads:   elements with an optional @start-order.  Writes: them, sorted.
  Params:  none.  Errors: none.
    fp:in-start-order($instances)  in start order; those without one (on a
                                   cycle of the constraints) last, in the
                                   order given
-->
<xsl:stylesheet version="3.0"
    xmlns:xsl="http://www.w3.org/1999/XSL/Transform"
    xmlns:xs="http://www.w3.org/2001/XMLSchema"
    xmlns:fp="urn:robomda:xslt:function:private"
    exclude-result-prefixes="#all">

  <xsl:function name="fp:in-start-order" as="element()*">
    <xsl:param name="instances" as="element()*"/>
    <xsl:perform-sort select="$instances">
      <xsl:sort select="empty(@start-order)"/>
      <xsl:sort select="xs:integer((@start-order, 0)[1])"/>
    </xsl:perform-sort>
  </xsl:function>
</xsl:stylesheet>
