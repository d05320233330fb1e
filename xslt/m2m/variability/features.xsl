<?xml version="1.0" encoding="UTF-8"?>
<!--
  xslt/m2m/variability/features.xsl - FeatureIDE feature models and
  configurations: which features a configuration selects, whether that
  selection is valid for the feature model, and the truth of a formula.

  Reads:   a FeatureIDE feature model (schemas/variability/1/featureide-model.xsd)
           and a FeatureIDE configuration
           (schemas/variability/1/featureide-configuration.xsd), both already
           valid against those schemas (the driver checks them).
  Writes:  nothing (a function module of xslt/m2m/configure.xsl).
  Params:  none.
  Public:  f:selected($configuration) the names of the selected features;
           f:holds($formula, $selected) the truth of a formula (var, not,
           conj, disj, imp, eq, in any namespace) under a selection;
           f:formula-text($formula) the formula written out;
           f:configuration-errors($model, $configuration) the error maps
           (f:fail-all) of a configuration invalid for its model;
           f:model-errors($model) those of a feature model robomda cannot use;
           f:where($node) the location id of a node of a file that is no
           XMI: "FILE#@/name.N/name.N...", which the driver maps to the
           node's line (src/robomda/diagnostics.py, XmiLocator).
  Errors:  VAR010 the configuration names a feature the model lacks;
           VAR012 the root feature is not selected; VAR013 a selected
           feature's parent is not; VAR014 a mandatory child of a selected
           feature is not selected; VAR015 an or-group with no child
           selected; VAR016 an alternative group without exactly one child
           selected; VAR017 a cross-tree constraint the selection breaks;
           VAR018 a group (and / or / alt) with no child feature (its
           selection is then not checked: VAR018 says it); VAR019 a
           constraint names a feature the model lacks. The configuration's
           errors are located in the configuration file, the model's in the
           feature model (docs/errors.md).
-->
<xsl:stylesheet version="3.0"
    xmlns:xsl="http://www.w3.org/1999/XSL/Transform"
    xmlns:xs="http://www.w3.org/2001/XMLSchema"
    xmlns:f="urn:robomda:xslt:function"
    xmlns:fp="urn:robomda:xslt:function:private"
    exclude-result-prefixes="#all">

  <xsl:key name="fp:feature" match="struct//*[@name]" use="@name"/>
  <xsl:key name="fp:configured" match="configuration/feature" use="@name"/>

  <!-- the location id of $node: its file, then its path of local names and
       positions among same-named siblings (no brackets: the id travels in
       "[xmi:id=...]") -->
  <xsl:function name="f:where" as="xs:string">
    <xsl:param name="node" as="element()"/>
    <xsl:variable name="file" as="xs:string" select="replace(string(base-uri($node)), '^file:(//)?', '')"/>
    <xsl:sequence select="$file || '#@' || string-join(
        for $a in $node/ancestor-or-self::* return
          '/' || local-name($a) || '.' || (1 + count($a/preceding-sibling::*[node-name() eq node-name($a)])), '')"/>
  </xsl:function>

  <xsl:function name="f:selected" as="xs:string*">
    <xsl:param name="configuration" as="document-node()"/>
    <xsl:sequence select="$configuration/configuration/feature[@manual = 'selected' or @automatic = 'selected']/string(@name)"/>
  </xsl:function>

  <xsl:function name="f:holds" as="xs:boolean">
    <xsl:param name="formula" as="element()"/>
    <xsl:param name="selected" as="xs:string*"/>
    <xsl:variable name="args" as="xs:boolean*" select="$formula/*[local-name() ne 'description'] ! f:holds(., $selected)"/>
    <xsl:choose>
      <xsl:when test="local-name($formula) eq 'var'"><xsl:sequence select="normalize-space($formula) = $selected"/></xsl:when>
      <xsl:when test="local-name($formula) eq 'not'"><xsl:sequence select="not($args[1])"/></xsl:when>
      <xsl:when test="local-name($formula) eq 'conj'"><xsl:sequence select="every $a in $args satisfies $a"/></xsl:when>
      <xsl:when test="local-name($formula) eq 'disj'"><xsl:sequence select="some $a in $args satisfies $a"/></xsl:when>
      <xsl:when test="local-name($formula) eq 'imp'"><xsl:sequence select="not($args[1]) or $args[2]"/></xsl:when>
      <xsl:when test="local-name($formula) eq 'eq'"><xsl:sequence select="$args[1] eq $args[2]"/></xsl:when>
      <!-- a rule: its one formula -->
      <xsl:otherwise><xsl:sequence select="$args[1]"/></xsl:otherwise>
    </xsl:choose>
  </xsl:function>

  <xsl:function name="f:formula-text" as="xs:string">
    <xsl:param name="formula" as="element()"/>
    <xsl:variable name="args" as="xs:string*" select="$formula/*[local-name() ne 'description'] ! fp:operand(.)"/>
    <xsl:choose>
      <xsl:when test="local-name($formula) eq 'var'"><xsl:sequence select="normalize-space($formula)"/></xsl:when>
      <xsl:when test="local-name($formula) eq 'not'"><xsl:sequence select="'not ' || $args[1]"/></xsl:when>
      <xsl:when test="local-name($formula) eq 'conj'"><xsl:sequence select="string-join($args, ' and ')"/></xsl:when>
      <xsl:when test="local-name($formula) eq 'disj'"><xsl:sequence select="string-join($args, ' or ')"/></xsl:when>
      <xsl:when test="local-name($formula) eq 'imp'"><xsl:sequence select="$args[1] || ' implies ' || $args[2]"/></xsl:when>
      <xsl:when test="local-name($formula) eq 'eq'"><xsl:sequence select="$args[1] || ' iff ' || $args[2]"/></xsl:when>
      <!-- a rule: its one formula -->
      <xsl:otherwise><xsl:sequence select="f:formula-text($formula/*[local-name() ne 'description'][1])"/></xsl:otherwise>
    </xsl:choose>
  </xsl:function>

  <xsl:function name="fp:operand" as="xs:string">
    <xsl:param name="formula" as="element()"/>
    <xsl:sequence select="if (local-name($formula) = ('var', 'not')) then f:formula-text($formula)
                          else '(' || f:formula-text($formula) || ')'"/>
  </xsl:function>

  <!-- the feature names a formula uses -->
  <xsl:function name="f:formula-features" as="element()*">
    <xsl:param name="formula" as="element()"/>
    <xsl:sequence select="$formula/descendant-or-self::*[local-name() eq 'var']"/>
  </xsl:function>

  <xsl:function name="f:model-errors" as="map(*)*">
    <xsl:param name="model" as="document-node()"/>
    <xsl:for-each select="$model/featureModel/struct//(child::and | child::or | child::alt)[not(child::and | child::or | child::alt | child::feature)]">
      <xsl:sequence select="map { 'code': 'VAR018', 'id': f:where(.), 'message':
          local-name() || '-group ''' || @name || ''' has no child feature' }"/>
    </xsl:for-each>
    <xsl:for-each select="$model/featureModel/constraints/rule//var[empty(key('fp:feature', normalize-space(), $model))]">
      <xsl:sequence select="map { 'code': 'VAR019', 'id': f:where(.), 'message':
          'a constraint names feature ''' || normalize-space() || ''', which the feature model does not have' }"/>
    </xsl:for-each>
  </xsl:function>

  <xsl:function name="f:configuration-errors" as="map(*)*">
    <xsl:param name="model" as="document-node()"/>
    <xsl:param name="configuration" as="document-node()"/>
    <xsl:variable name="selected" as="xs:string*" select="f:selected($configuration)"/>
    <xsl:variable name="root" as="element(configuration)" select="$configuration/configuration"/>
    <xsl:for-each select="$root/feature[empty(key('fp:feature', @name, $model))]">
      <xsl:sequence select="map { 'code': 'VAR010', 'id': f:where(.), 'message':
          'the configuration names feature ''' || @name || ''', which the feature model does not have' }"/>
    </xsl:for-each>
    <xsl:for-each select="$model/featureModel/struct/*[not(@name = $selected)]">
      <xsl:sequence select="map { 'code': 'VAR012', 'id': fp:entry($root, @name), 'message':
          'the root feature ''' || @name || ''' is not selected' }"/>
    </xsl:for-each>
    <xsl:for-each select="$model/featureModel/struct//*[@name = $selected]">
      <xsl:sequence select="fp:group-errors(., $root, $selected)"/>
    </xsl:for-each>
    <xsl:for-each select="$model/featureModel/constraints/rule[not(f:holds(., $selected))]">
      <xsl:sequence select="map { 'code': 'VAR017', 'id': f:where($root), 'message':
          'the selection breaks the constraint ''' || f:formula-text(.) || ''' of the feature model (rule '
          || count(preceding-sibling::rule) + 1 || ')' }"/>
    </xsl:for-each>
  </xsl:function>

  <!-- the errors about selected feature $node of the model: its parent, its children -->
  <xsl:function name="fp:group-errors" as="map(*)*">
    <xsl:param name="node" as="element()"/>
    <xsl:param name="root" as="element(configuration)"/>
    <xsl:param name="selected" as="xs:string*"/>
    <xsl:variable name="parent" as="element()?" select="$node/parent::*[@name]"/>
    <xsl:variable name="children" as="element()*" select="$node/(child::and | child::or | child::alt | child::feature)"/>
    <xsl:variable name="chosen" as="element()*" select="$children[@name = $selected]"/>
    <xsl:if test="exists($parent) and not($parent/@name = $selected)">
      <xsl:sequence select="map { 'code': 'VAR013', 'id': fp:entry($root, $node/@name), 'message':
          'feature ''' || $node/@name || ''' is selected but its parent ''' || $parent/@name || ''' is not' }"/>
    </xsl:if>
    <xsl:if test="local-name($node) eq 'and'">
      <xsl:for-each select="$children[@mandatory = ('true', '1')][not(@name = $selected)]">
        <xsl:sequence select="map { 'code': 'VAR014', 'id': fp:entry($root, @name), 'message':
            'feature ''' || @name || ''' is mandatory under selected ''' || $node/@name || ''' but not selected' }"/>
      </xsl:for-each>
    </xsl:if>
    <xsl:if test="local-name($node) eq 'or' and exists($children) and empty($chosen)">
      <xsl:sequence select="map { 'code': 'VAR015', 'id': fp:entry($root, $node/@name), 'message':
          'or-group ''' || $node/@name || ''' is selected but none of its features is (one or more of: '
          || string-join($children/@name, ', ') || ')' }"/>
    </xsl:if>
    <xsl:if test="local-name($node) eq 'alt' and exists($children) and count($chosen) ne 1">
      <xsl:sequence select="map { 'code': 'VAR016', 'id': fp:entry($root, $node/@name), 'message':
          'alternative group ''' || $node/@name || ''' needs exactly one of its features (' || string-join($children/@name, ', ')
          || ') selected, the configuration selects ' || (if (empty($chosen)) then 'none'
          else string-join($chosen/@name, ', ')) }"/>
    </xsl:if>
  </xsl:function>

  <!-- where the configuration states feature $name: its entry, else the configuration itself -->
  <xsl:function name="fp:entry" as="xs:string">
    <xsl:param name="root" as="element(configuration)"/>
    <xsl:param name="name" as="xs:string"/>
    <xsl:sequence select="f:where((key('fp:configured', $name, root($root))[1], $root)[1])"/>
  </xsl:function>
</xsl:stylesheet>
